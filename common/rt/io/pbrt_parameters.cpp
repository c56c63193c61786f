#include "rt/io/pbrt_parameters.hpp"

#include <cmath>
#include <cstdio>
#include <span>

#include "rt/core/errors.hpp"
#include "rt/io/pbrt_spectra.hpp"

namespace rt {
namespace {

// What the types of pbrt-v4 hold; "point" and "vector" are pbrt-v3's names of point3 and vector3, "color"
// of rgb.
constexpr std::string_view kNumberTypes[] = {"integer", "float", "rgb", "color", "point2", "point3", "point",
                                             "normal", "normal3", "vector", "vector3", "blackbody"};
constexpr std::string_view kStringTypes[] = {"string", "texture", "bool"};

bool one_of(std::string_view s, std::span<const std::string_view> list) {
    for (std::string_view x : list) {
        if (x == s) return true;
    }
    return false;
}

}  // namespace

std::string show_pbrt_number(double x) {
    char text[32];
    if (x == std::floor(x) && std::abs(x) < 1e15) {
        std::snprintf(text, sizeof text, "%.0f", x);
    } else {
        std::snprintf(text, sizeof text, "%.9g", x);
    }
    return text;
}

std::vector<PbrtParameter> read_pbrt_parameters(const std::vector<PbrtToken>& tokens, std::size_t& at,
                                                const std::string& place) {
    std::vector<PbrtParameter> list;
    while (at < tokens.size() && tokens[at].kind == PbrtTokenKind::kString) {
        PbrtParameter p;
        p.where = tokens[at];
        const std::string& decl = tokens[at].text;
        const std::size_t space = decl.find(' ');
        const std::size_t name_at = decl.find_first_not_of(' ', space);
        if (space == std::string::npos || name_at == std::string::npos ||
            decl.find(' ', name_at) != std::string::npos) {
            throw InputError(pbrt_location(place, p.where) + "a parameter must be declared as \"type name\", got \"" +
                             decl + "\"");
        }
        p.type = decl.substr(0, space);
        p.name = decl.substr(name_at);
        const bool numbers = one_of(p.type, kNumberTypes), strings = one_of(p.type, kStringTypes);
        if (!numbers && !strings && p.type != "spectrum") {
            throw InputError(pbrt_location(place, p.where) + "unknown parameter type \"" + p.type +
                             "\"; pbrt-v4's are integer, float, bool, string, rgb, spectrum, blackbody, point2, "
                             "point3, normal, vector, texture");
        }
        for (const PbrtParameter& q : list) {
            if (q.name == p.name) {
                throw InputError(pbrt_location(place, p.where) + "parameter \"" + p.name + "\" given twice");
            }
        }
        ++at;
        const bool bracket = at < tokens.size() && tokens[at].kind == PbrtTokenKind::kOpen;
        if (bracket) ++at;
        std::size_t count = 0;
        while (at < tokens.size() && (bracket || count == 0)) {
            const PbrtToken& v = tokens[at];
            if (v.kind == PbrtTokenKind::kClose && bracket) break;
            const bool is_bool_word = p.type == "bool" && v.kind == PbrtTokenKind::kWord;
            if (v.kind == PbrtTokenKind::kNumber && (numbers || p.type == "spectrum")) {
                p.numbers.push_back(v.number);
            } else if ((v.kind == PbrtTokenKind::kString && (strings || p.type == "spectrum")) || is_bool_word) {
                p.strings.push_back(v.text);
            } else {
                throw InputError(pbrt_location(place, v) + "\"" + decl + "\": expected " +
                                 (numbers ? "a number" : "a quoted string") + (bracket ? " or ]" : "") + ", got " +
                                 (v.kind == PbrtTokenKind::kString ? "\"" + v.text + "\"" : v.text));
            }
            ++at;
            ++count;
        }
        if (bracket) {
            if (at >= tokens.size()) {
                throw InputError(pbrt_location(place, p.where) + "\"" + decl + "\": its [ is not closed by ]");
            }
            ++at;
        }
        if (count == 0) throw InputError(pbrt_location(place, p.where) + "\"" + decl + "\": no value");
        if (!p.numbers.empty() && !p.strings.empty()) {
            throw InputError(pbrt_location(place, p.where) + "\"" + decl + "\": mixes numbers and strings");
        }
        list.push_back(std::move(p));
    }
    return list;
}

PbrtParameter* PbrtParameters::find(std::string_view name, std::initializer_list<std::string_view> types) {
    for (PbrtParameter& p : list_) {
        if (p.name != name) continue;
        p.used = true;
        for (std::string_view t : types) {
            if (p.type == t) return &p;
        }
        std::string expected;
        for (std::string_view t : types) expected += (expected.empty() ? "" : " or ") + std::string(t);
        fail(name, "must be of type " + expected + ", got " + p.type);
    }
    return nullptr;
}

void PbrtParameters::fail(std::string_view name, const std::string& what) const {
    for (const PbrtParameter& p : list_) {
        if (p.name == name) {
            throw InputError(pbrt_location(place_, p.where) + owner_ + ": \"" + p.type + " " + p.name + "\": " + what);
        }
    }
    throw InputError(directive_ + owner_ + ": " + what);
}

bool PbrtParameters::has(std::string_view name) const {
    for (const PbrtParameter& p : list_) {
        if (p.name == name) return true;
    }
    return false;
}

bool PbrtParameters::ignore(std::string_view name) {
    for (PbrtParameter& p : list_) {
        if (p.name == name) p.used = true;
    }
    return has(name);
}

std::vector<double> PbrtParameters::reals(std::string_view name, std::string_view type, std::size_t group) {
    const PbrtParameter* p = nullptr;
    if (type == "point3") p = find(name, {"point3", "point"});
    else if (type == "normal") p = find(name, {"normal", "normal3"});
    else if (type == "vector") p = find(name, {"vector3", "vector"});
    else p = find(name, {type});
    if (!p) return {};
    if (!p->strings.empty() || p->numbers.size() % group != 0) {
        fail(name, "must hold a multiple of " + std::to_string(group) + " numbers, got " +
                       std::to_string(p->numbers.size() + p->strings.size()) + " values");
    }
    return p->numbers;
}

std::optional<double> PbrtParameters::real(std::string_view name) {
    const std::vector<double> v = reals(name, "float", 1);
    if (v.empty()) return std::nullopt;
    if (v.size() != 1) fail(name, "must be one number, got " + std::to_string(v.size()));
    return v[0];
}

std::vector<int> PbrtParameters::integers(std::string_view name) {
    std::vector<int> out;
    for (const double x : reals(name, "integer", 1)) {
        if (!(x == std::floor(x) && x >= -2147483648.0 && x <= 2147483647.0)) {
            fail(name, "must hold whole numbers in [-2147483648, 2147483647], got " + show_pbrt_number(x));
        }
        out.push_back(int(x));
    }
    return out;
}

std::optional<int> PbrtParameters::integer(std::string_view name) {
    const std::vector<int> v = integers(name);
    if (v.empty()) return std::nullopt;
    if (v.size() != 1) fail(name, "must be one whole number, got " + std::to_string(v.size()));
    return v[0];
}

std::optional<bool> PbrtParameters::boolean(std::string_view name) {
    const PbrtParameter* p = find(name, {"bool"});
    if (!p) return std::nullopt;
    if (p->strings.size() != 1 || (p->strings[0] != "true" && p->strings[0] != "false")) {
        fail(name, "must be one of true or false");
    }
    return p->strings[0] == "true";
}

std::optional<std::string> PbrtParameters::string(std::string_view name) {
    const PbrtParameter* p = find(name, {"string"});
    if (!p) return std::nullopt;
    if (p->strings.size() != 1) fail(name, "must be one string, got " + std::to_string(p->strings.size()));
    return p->strings[0];
}

std::optional<Vec3d> PbrtParameters::color(std::string_view name) {
    const PbrtParameter* p = find(name, {"rgb", "color", "spectrum", "blackbody", "texture"});
    if (!p) return std::nullopt;
    if (p->type == "texture") fail(name, "the course reads no texture here; give an rgb value");
    if (p->type == "blackbody") {
        if (p->numbers.size() != 1) fail(name, "must be one temperature in kelvin");
        const double kelvin = p->numbers[0];
        if (!(kelvin >= kBlackbodyLeast && kelvin <= kBlackbodyMost)) {
            fail(name, "must be in [1667, 25000] kelvin (the range of the course's conversion), got " +
                           show_pbrt_number(kelvin));
        }
        return pbrt_blackbody_rgb(kelvin);
    }
    if (p->type == "spectrum") {
        if (p->strings.size() != 1) {
            fail(name, "the course reads a spectrum only by name (" + std::string(kPbrtNamedSpectra) +
                           "); give other values as rgb");
        }
        const std::optional<Vec3d> named = pbrt_named_spectrum(p->strings[0]);
        if (!named) {
            fail(name, "unknown named spectrum \"" + p->strings[0] + "\"; the course knows " +
                           std::string(kPbrtNamedSpectra));
        }
        return named;
    }
    if (p->numbers.size() != 3) fail(name, "must be 3 numbers, got " + std::to_string(p->numbers.size()));
    return Vec3d(p->numbers[0], p->numbers[1], p->numbers[2]);
}

std::optional<std::string> PbrtParameters::texture(std::string_view name) {
    for (const PbrtParameter& p : list_) {
        if (p.name == name && p.type != "texture") return std::nullopt;
    }
    const PbrtParameter* p = find(name, {"texture"});
    if (!p) return std::nullopt;
    if (p->strings.size() != 1) fail(name, "must name one texture, got " + std::to_string(p->strings.size()));
    return p->strings[0];
}

std::optional<Vec3d> PbrtParameters::point3(std::string_view name) {
    const std::vector<double> v = reals(name, "point3", 3);
    if (v.empty()) return std::nullopt;
    if (v.size() != 3) fail(name, "must be one point (3 numbers), got " + std::to_string(v.size()));
    return Vec3d(v[0], v[1], v[2]);
}

void PbrtParameters::refuse_unused(std::string_view supported) const {
    for (const PbrtParameter& p : list_) {
        if (!p.used) {
            throw InputError(pbrt_location(place_, p.where) + owner_ + ": parameter \"" + p.type + " " + p.name +
                             "\" is not supported by the course (it reads " + std::string(supported) + ")");
        }
    }
}

}  // namespace rt
