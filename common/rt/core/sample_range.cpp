#include "rt/core/sample_range.hpp"

#include <algorithm>
#include <charconv>

#include "rt/core/errors.hpp"
#include "rt/core/whole_number.hpp"

namespace rt {
namespace {

// Read as strictly as every whole number of a flag (whole_number.hpp): no sign, no leading 0.
bool parse_int(std::string_view text, int& value) {
    if (!whole_number_error(text, false).empty()) return false;
    const char* end = text.data() + text.size();
    const auto [stop, error] = std::from_chars(text.data(), end, value);
    return !text.empty() && error == std::errc() && stop == end;
}

}  // namespace

SampleRange parse_sample_range(std::string_view text, int total) {
    const auto colon = text.find(':');
    SampleRange range;
    const bool parsed = colon != std::string_view::npos && parse_int(text.substr(0, colon), range.first) &&
                        parse_int(text.substr(colon + 1), range.end);
    if (!parsed || range.first < 0 || range.first >= range.end || range.end > total) {
        throw InputError("must be A:B with 0 <= A < B <= " + std::to_string(total) +
                         " (the samples per pixel), got " + std::string(text));
    }
    return range;
}

std::string to_string(const SampleRange& range) {
    return std::to_string(range.first) + ":" + std::to_string(range.end);
}

SampleRange split_range(const SampleRange& whole, int parts, int index) {
    const int base = whole.size() / parts, larger = whole.size() % parts;
    const int first = whole.first + index * base + std::min(index, larger);
    return {first, first + base + (index < larger ? 1 : 0)};
}

}  // namespace rt
