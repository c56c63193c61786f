#include "rt/core/whole_number.hpp"

#include <charconv>
#include <cstdint>
#include <string>

#include "rt/core/printable.hpp"

namespace rt {

std::string whole_number_error(std::string_view text, bool is_signed) {
    const char* first = text.data();
    const char* last = text.data() + text.size();
    const std::string expected = is_signed ? "a whole number (decimal digits, a '-' before them if negative)"
                                           : "a whole number >= 0 (decimal digits only)";
    if (is_signed && first != last && *first == '-') ++first;
    if (first == last) return "must be " + expected + ", got " + shown_value(text);
    for (const char* c = first; c != last; ++c) {
        if (*c < '0' || *c > '9') return "must be " + expected + ", got " + shown_value(text);
    }
    // CLI11 would read a leading 0 as octal (010 as 8).
    if (*first == '0' && last - first > 1) return "must be " + expected + " without a leading 0, got " + shown_value(text);

    std::from_chars_result r{};
    if (is_signed) {
        std::int64_t value = 0;
        r = std::from_chars(text.data(), last, value);
    } else {
        std::uint64_t value = 0;
        r = std::from_chars(text.data(), last, value);
    }
    if (r.ec == std::errc::result_out_of_range) {
        return "must be " + expected + " that fits in 64 bits (at most " +
               (is_signed ? std::to_string(INT64_MAX) : std::to_string(UINT64_MAX)) + "), got " + shown_value(text);
    }
    return r.ec == std::errc() && r.ptr == last ? "" : "must be " + expected + ", got " + shown_value(text);
}

}  // namespace rt
