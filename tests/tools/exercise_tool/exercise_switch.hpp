// Only in the scratch editions of `exercises.py deps` (copied there as common/rt/exercise_switch.hpp): every
// marked exercise keeps its body and starts with
//     static const bool stubbed_here = rt::exercise_switch::stubbed("chNN.name");
//     if (stubbed_here) throw std::logic_error("not implemented: chNN.name ...");
// so one build can stand for the edition with any one exercise stubbed, chosen when a test runs:
//   RT_STUB_EXERCISE=chNN.name  that exercise throws as in the student edition, the others run as written
//                               (a,b,c: those three);
//   RT_STUB_EXERCISE=*          every exercise throws: the student edition, at run time;
//   RT_EXERCISE_LOG=FILE        each exercise the process reaches appends its name to FILE;
//   RT_WRONG_SOLUTION=chNN.name:K  that exercise runs its K-th wrong solution (tests/wrong_solutions/) instead.
// The static is initialised on the first call only, so each exercise is looked up (and logged) once per
// process, and a test that never reaches an exercise cannot depend on it.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace rt::exercise_switch {

inline bool stubbed(const char* exercise) {
    if (const char* log = std::getenv("RT_EXERCISE_LOG")) {
        if (std::FILE* file = std::fopen(log, "a")) {
            std::fprintf(file, "%s\n", exercise);
            std::fclose(file);
        }
    }
    const char* chosen = std::getenv("RT_STUB_EXERCISE");
    if (chosen == nullptr) return false;
    if (std::strcmp(chosen, "*") == 0) return true;
    const std::size_t length = std::strlen(exercise);
    for (const char* name = chosen;; ++name) {  // one of the comma-separated names
        if (std::strncmp(name, exercise, length) == 0 && (name[length] == ',' || name[length] == '\0')) return true;
        name = std::strchr(name, ',');
        if (name == nullptr) return false;
    }
}

// Which of the exercise's wrong solutions (tests/wrong_solutions/) runs instead of its body: K when
// RT_WRONG_SOLUTION is "chNN.name:K", else 0 (the body as written).
inline int wrong_solution(const char* exercise) {
    const char* chosen = std::getenv("RT_WRONG_SOLUTION");
    const std::size_t length = std::strlen(exercise);
    if (chosen == nullptr || std::strncmp(chosen, exercise, length) != 0 || chosen[length] != ':') return 0;
    return std::atoi(chosen + length + 1);
}

}  // namespace rt::exercise_switch
