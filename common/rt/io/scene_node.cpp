#include "rt/io/scene_node.hpp"

#include <sstream>

#include "rt/core/did_you_mean.hpp"
#include "rt/core/printable.hpp"

namespace rt::scene_reading {

std::string show(double x) {
    std::ostringstream out;
    out << x;
    return out.str();
}

std::string shown_name(std::string_view s) {
    return printable(s, 64);
}

std::string quote(std::string_view s) {
    return "\"" + shown_name(s) + "\"";
}

std::string show_fraction(double x) {
    std::string text = show(x);
    if (text.find_first_of(".e") == std::string::npos) text += ".0";
    return text;
}

std::string show(const Vec3& v) {
    return "[" + show(v.x) + ", " + show(v.y) + ", " + show(v.z) + "]";
}

bool normalisable(const Vec3& v) {
    const Real length = glm::length(v);
    return length > 0 && std::isfinite(length) && is_finite(v / length);
}

std::string suggestion(std::string_view word, std::span<const std::string_view> candidates) {
    const auto match = closest_match(word, candidates);
    return match ? " (did you mean " + quote(*match) + "?)" : "";
}

}  // namespace rt::scene_reading
