// A pbrt-v4 directive's parameter list, `"float radius" [ 1 ]`: a type, a name and values, with or without
// brackets. Each lookup checks the type, the count and the range, and fails with the parameter's place
// ("scene.pbrt:40:5: "float radius": must be > 0, got -1"); a parameter that no lookup asked for is refused by
// refuse_unused(), naming what the course supports.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "rt/core/math.hpp"
#include "rt/io/pbrt_tokens.hpp"

namespace rt {

struct PbrtParameter {
    std::string type;  // integer, float, bool, string, rgb, spectrum, point2, point3, normal, texture, ...
    std::string name;
    std::vector<double> numbers;
    std::vector<std::string> strings;  // string, texture, spectrum by name; bool as "true"/"false"
    PbrtToken where;                   // the "type name" string
    bool used = false;
};

class PbrtParameters {
  public:
    // `file`: the file as messages name it; `directive`: "FILE:LINE:COLUMN: " of the directive; `owner`:
    // "Shape \"sphere\"".
    PbrtParameters(std::vector<PbrtParameter> list, std::string file, std::string directive, std::string owner)
        : list_(std::move(list)), place_(std::move(file)), directive_(std::move(directive)), owner_(std::move(owner)) {}

    bool has(std::string_view name) const;
    std::optional<double> real(std::string_view name);  // float
    std::optional<int> integer(std::string_view name);  // one integer
    std::vector<int> integers(std::string_view name);   // integer list (empty when absent)
    std::vector<double> reals(std::string_view name, std::string_view type, std::size_t group);
    std::optional<bool> boolean(std::string_view name);
    std::optional<std::string> string(std::string_view name);
    // rgb, or spectrum by one of the named metal spectra (pbrt_spectra.hpp); the value in linear RGB.
    std::optional<Vec3d> color(std::string_view name);
    // The texture a "texture NAME" parameter names; nothing when it is absent or of another type.
    std::optional<std::string> texture(std::string_view name);
    std::optional<Vec3d> point3(std::string_view name);

    // Marks a parameter as read without using it, and returns whether it was given.
    bool ignore(std::string_view name);
    [[noreturn]] void fail(std::string_view name, const std::string& what) const;
    // "PLACE:LINE:COLUMN: " of the directive that holds the list.
    const std::string& place() const { return directive_; }
    // Throws for the first parameter no lookup read: "unknown parameter ... (the course reads: ...)".
    void refuse_unused(std::string_view supported) const;

  private:
    PbrtParameter* find(std::string_view name, std::initializer_list<std::string_view> types);

    std::vector<PbrtParameter> list_;
    std::string place_;
    std::string directive_;
    std::string owner_;  // "Shape \"sphere\"", for messages
};

// A number in a message: whole ones in full (2147483648), others to 9 digits.
std::string show_pbrt_number(double x);

// Reads the parameter list that starts at tokens[at] (strings "type name" each followed by a value or a
// bracketed list), up to the next directive; `at` moves past it.
std::vector<PbrtParameter> read_pbrt_parameters(const std::vector<PbrtToken>& tokens, std::size_t& at,
                                                const std::string& place);

}  // namespace rt
