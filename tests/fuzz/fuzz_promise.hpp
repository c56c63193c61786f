// What a fuzz target checks of every input it is given: a promise that, broken, stops the fuzzer (abort) with
// the target's name and the promise, so that libFuzzer keeps the input that broke it.
#pragma once

#include <cstdio>
#include <cstdlib>

inline void expect_promise(bool holds, const char* fuzzer, const char* promise) {
    if (holds) return;
    std::fprintf(stderr, "%s: broken promise: %s\n", fuzzer, promise);
    std::abort();
}
