// Only in the student edition (copied there as common/rt/exercise_warnings.hpp): each exercise sits between
//     RT_YOUR_CODE_BEGIN  ...  RT_YOUR_CODE_END
// so that a warning in what you write there stays a warning, wherever the file is included, while the rest
// of the course still builds with warnings as errors. Read the warnings all the same: most are bugs.
#pragma once

#define RT_YOUR_CODE_BEGIN                                                                                    \
    _Pragma("GCC diagnostic push") _Pragma("GCC diagnostic warning \"-Wall\"")                                \
        _Pragma("GCC diagnostic warning \"-Wextra\"") _Pragma("GCC diagnostic warning \"-Wpedantic\"")        \
            _Pragma("GCC diagnostic warning \"-Wshadow\"") _Pragma("GCC diagnostic warning \"-Wconversion\"")
#define RT_YOUR_CODE_END _Pragma("GCC diagnostic pop")
