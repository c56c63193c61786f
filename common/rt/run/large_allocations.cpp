#include "rt/run/large_allocations.hpp"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace rt {

void map_large_allocations_apart() {
#if defined(__GLIBC__)
    mallopt(M_MMAP_THRESHOLD, 4 << 20);
#endif
}

}  // namespace rt
