// The filters' one parallel loop: rows handed to the threads from an atomic counter. Every output pixel is
// computed from the inputs alone by the same code, so the image is the same bits for any thread count.
#pragma once

#include <functional>

namespace rt {

// Calls row(y) once for every y in [0, height), on `threads` threads (0: one per core).
void for_each_row(int height, int threads, const std::function<void(int)>& row);

}  // namespace rt
