// Large allocations handed back to the system when freed. glibc maps a block of 128 KiB or more apart from
// its heap, but after the first such block is freed it raises that threshold (up to 32 MiB), and later large
// blocks come from the heap, which keeps them once freed. A World of 10^6 triangles frees arrays of 4 MB to
// 48 MB step after step, few of them reused by the next step's arrays of other sizes: 23 MB of its peak of
// memory were such blocks. A fixed threshold of 4 MiB keeps every larger block apart, unmapped when freed.
#pragma once

namespace rt {

// Called once, before the run allocates: blocks of 4 MiB and more are mapped apart from the heap.
void map_large_allocations_apart();

}  // namespace rt
