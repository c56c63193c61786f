// The memory a run may take for its buffers: half of this machine's memory, and half of what this process
// may use (ulimit -v). Checked before a large allocation, so that a size too large is refused by name
// (exit 2) instead of failing with std::bad_alloc.
#pragma once

#include <string>

namespace rt {

// Throws InputError "WHAT needs N GB of buffers, more than half of ..." (naming the tighter limit) when
// `bytes` do not fit.
void check_fits_in_memory(double bytes, const std::string& what);

}  // namespace rt
