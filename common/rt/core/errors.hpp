// The two ways a run can fail: bad input from the user (exit 2) or a failure of the program (exit 1).
#pragma once

#include <stdexcept>
#include <string>

namespace rt {

// A scene file, a flag or a path the user gave is wrong. The message names the place and what was expected.
class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;
inline constexpr int kExitBadInput = 2;

}  // namespace rt
