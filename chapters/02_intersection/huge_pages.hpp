// Large arrays on huge pages. The first touch of each fresh 4 KiB page costs a page fault, and building the
// BVH of 10^6 triangles touches about 200 MB of fresh memory: its faults took half the build's time. Linux
// backs a region advised MADV_HUGEPAGE with 2 MiB pages (transparent huge pages), 512 times fewer faults.
// It is only advice: where the kernel does not take it, or the array is small, nothing changes.
#pragma once

#include <cstddef>
#include <vector>

namespace rt {

// Advises the whole 2 MiB pages inside [data, data + bytes).
void advise_huge_pages(const void* data, std::size_t bytes);

// v.reserve(n), on huge pages where its storage spans any.
template <typename T>
void reserve_on_huge_pages(std::vector<T>& v, std::size_t n) {
    v.reserve(n);
    advise_huge_pages(v.data(), v.capacity() * sizeof(T));
}

}  // namespace rt
