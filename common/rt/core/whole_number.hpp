// The strict reading of a whole number, the same for every flag that takes one (strict_flags.hpp) and for
// the two ends of --samples A:B (sample_range.hpp).
#pragma once

#include <string>
#include <string_view>

namespace rt {

// Decimal digits only, no leading 0, a leading '-' only when `is_signed`, within 64 bits. Returns what is
// wrong ("must be a whole number >= 0 (decimal digits only), got \"-0\""), or "" when `text` is one.
std::string whole_number_error(std::string_view text, bool is_signed);

}  // namespace rt
