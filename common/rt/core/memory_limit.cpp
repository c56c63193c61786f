#include "rt/core/memory_limit.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <cstdio>

#include "rt/core/errors.hpp"

namespace rt {
namespace {

std::string gigabytes(double bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f GB", bytes / 1e9);
    return text;
}

}  // namespace

void check_fits_in_memory(double bytes, const std::string& what) {
    const double memory = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGESIZE));
    rlimit limit{};
    const bool limited = getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY;
    const double process = limited ? double(limit.rlim_cur) : 0;
    const std::string needs = what + " needs " + gigabytes(bytes) + " of buffers, more than half of ";
    if (limited && (!(memory > 0) || process < memory) && bytes > process / 2) {
        throw InputError(needs + "the " + gigabytes(process) + " this process may use (ulimit -v)");
    }
    if (memory > 0 && bytes > memory / 2) {
        throw InputError(needs + "this machine's " + gigabytes(memory) + " of memory");
    }
    if (limited && bytes > process / 2) {
        throw InputError(needs + "the " + gigabytes(process) + " this process may use (ulimit -v)");
    }
}

}  // namespace rt
