// Reading a scene file: a JSON value and its place in the file ("shapes[3].radius"). Every read checks the
// value's type and range and fails with one line that names the file and the place (scene_loader.hpp). The
// other scene_*.cpp files read materials, shapes and lights with it.
#pragma once

#include <charconv>
#include <cmath>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <string_view>

#include "rt/core/errors.hpp"
#include "rt/core/math.hpp"
#include "rt/io/scene_loader.hpp"

namespace rt::scene_reading {

using Json = nlohmann::json;

inline constexpr double kLargestNumber = kLargestSceneNumber;

std::string show(double x);
std::string show(const Vec3& v);
// A name from the file in a message: escaped so that the message stays one line (printable.hpp), and cut
// after 64 bytes.
std::string shown_name(std::string_view s);
std::string quote(std::string_view s);
// A number written with a fraction or an exponent, shown as one: 32.0 stays "32.0", not "32".
std::string show_fraction(double x);
// A vector that float arithmetic can normalise: its length in Real is positive and finite.
bool normalisable(const Vec3& v);
// " (did you mean "x"?)" when one of the candidates is close to the word, or nothing.
std::string suggestion(std::string_view word, std::span<const std::string_view> candidates);

// A value in the scene file and its place ("shapes[3].radius"); every read checks type and range.
class Node {
  public:
    Node(const Json& value, std::string place, const std::string& file)
        : value_(value), place_(std::move(place)), file_(file) {}

    [[noreturn]] void fail(const std::string& what) const {
        throw InputError(file_ + ": " + (place_.empty() ? "" : place_ + ": ") + what);
    }
    const std::string& place() const { return place_; }
    const Json& json() const { return value_; }

    bool has(const char* key) const { return value_.contains(key); }
    Node operator[](const char* key) const {
        if (!value_.contains(key)) fail("missing required field " + quote(key));
        return Node(value_.at(key), child_place(key), file_);
    }
    Node element(std::size_t i) const {
        return Node(value_.at(i), place_ + "[" + std::to_string(i) + "]", file_);
    }

    // `owner` says whose keys these are in the message ("a mirror material"), when the type decides them.
    void expect_object(std::span<const std::string_view> allowed_keys, const std::string& owner = "") const {
        if (!value_.is_object()) fail("must be an object, got " + std::string(value_.type_name()));
        for (const auto& [key, unused] : value_.items()) {
            bool known = false;
            for (std::string_view k : allowed_keys) known = known || k == key;
            if (!known) {
                throw InputError(file_ + ": " + child_place(key) + ": unknown key" +
                                 (owner.empty() ? "" : " for " + owner) + suggestion(key, allowed_keys));
            }
        }
    }
    std::size_t array_size() const {
        if (!value_.is_array()) fail("must be an array, got " + std::string(value_.type_name()));
        return value_.size();
    }
    std::string string() const {
        if (!value_.is_string()) fail("must be a string, got " + std::string(value_.type_name()));
        return value_.get<std::string>();
    }
    bool boolean() const {
        if (!value_.is_boolean()) fail("must be true or false, got " + std::string(value_.type_name()));
        return value_.get<bool>();
    }
    double number() const {
        if (!value_.is_number()) fail("must be a number, got " + std::string(value_.type_name()));
        const double x = value_.get<double>();
        if (!std::isfinite(x) || std::abs(x) > kLargestNumber) {
            fail("must be a finite number of magnitude at most " + show(kLargestNumber) + ", got " + show(x));
        }
        return x;
    }
    Real real() const { return Real(number()); }
    // The range is checked on the value as it will be used, in Real: 179.99999999 is 180 in float, and 1e-50
    // is 0.
    Real real_in(double low, double high, bool low_open, bool high_open) const {
        const double x = number();
        const double r = double(Real(x));
        if ((low_open ? r <= low : r < low) || (high_open ? r >= high : r > high)) {
            fail("must be in " + std::string(low_open ? "(" : "[") + show(low) + ", " + show(high) +
                 (high_open ? ")" : "]") + ", got " + as_used(x));
        }
        return Real(x);
    }
    Real positive() const {
        const double x = number();
        if (!(Real(x) > 0)) fail("must be > 0, got " + as_used(x));
        return Real(x);
    }
    int integer(long long low, long long high) const {
        const std::string range = "[" + std::to_string(low) + ", " + std::to_string(high) + "]";
        if (!value_.is_number_integer()) {
            fail("must be a whole number in " + range + ", got " +
                 (value_.is_number() ? show_fraction(value_.get<double>()) : std::string(value_.type_name())));
        }
        if (value_.is_number_unsigned() &&
            value_.get<unsigned long long>() > static_cast<unsigned long long>(high)) {
            fail("must be in " + range + ", got " + std::to_string(value_.get<unsigned long long>()));
        }
        const long long x = value_.get<long long>();
        if (x < low || x > high) fail("must be in " + range + ", got " + std::to_string(x));
        return int(x);
    }
    Vec3 vec3() const {
        if (!value_.is_array() || value_.size() != 3) {
            fail("must be an array of 3 numbers, got " + (value_.is_array()
                                                              ? "an array of " + std::to_string(value_.size())
                                                              : std::string(value_.type_name())));
        }
        return {element(0).real(), element(1).real(), element(2).real()};
    }
    // A direction: float must be able to normalise it (not zero, not so short that its length underflows).
    Vec3 direction() const {
        const Vec3 v = vec3();
        if (!normalisable(v)) fail("must be a direction of non-zero length, got " + show(v));
        return v;
    }
    Color color_in(double high) const {
        const Vec3 c = vec3();
        for (int i = 0; i < 3; ++i) {
            if (c[i] < 0 || c[i] > high) {
                element(std::size_t(i)).fail("must be in [0, " + show(high) + "], got " + show(c[i]));
            }
        }
        return c;
    }

  private:
    // The value as given, and what Real makes of it when that differs: "1e-50, which is 0 in float".
    static std::string as_used(double x) {
        if (double(Real(x)) == x) return show(x);
        char text[32];
        const auto end = std::to_chars(text, text + sizeof text, x).ptr;  // the shortest exact form
        constexpr const char* kRealName = sizeof(Real) == sizeof(float) ? "float" : "double";
        return std::string(text, end) + ", which is " + show(double(Real(x))) + " in " + kRealName;
    }
    std::string child_place(std::string_view key) const {
        return place_.empty() ? shown_name(key) : place_ + "." + shown_name(key);
    }

    const Json& value_;
    std::string place_;
    const std::string& file_;
};

}  // namespace rt::scene_reading
