// An enum's names, written once. A chapter gives each enum of its flags one table of {value, name} pairs,
// returned by a `names_of(E)` beside the enum; that table alone serves to_string, from_string (whose error
// lists the names) and the flag that takes them (enum_flag.hpp).
#pragma once

#include <array>
#include <concepts>
#include <cstddef>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "rt/core/errors.hpp"
#include "rt/core/printable.hpp"

namespace rt {

template <class E>
struct EnumName {
    E value;
    std::string_view name;
};

template <class E, std::size_t N>
struct EnumNames {
    std::string_view flag;  // the flag that takes these names, as messages name it: "--sampling"
    std::array<EnumName<E>, N> names;
};

// What names_of returns: enum_names<E>("--flag", {{E::kA, "a"}, {E::kB, "b"}}).
template <class E, std::size_t N>
constexpr EnumNames<E, N> enum_names(std::string_view flag, const EnumName<E> (&names)[N]) {
    return {flag, std::to_array(names)};
}

// An enum with a names_of(E) table, found beside it by argument-dependent lookup.
template <class E>
concept NamedEnum = std::is_enum_v<E> && requires(E e) {
    names_of(e);
};

template <NamedEnum E>
constexpr std::string_view to_string(E value) {
    for (const EnumName<E>& entry : names_of(value).names)
        if (entry.value == value) return entry.name;
    return "?";
}

// Every name, in the table's order.
template <NamedEnum E>
std::vector<std::string> all_names() {
    std::vector<std::string> names;
    for (const EnumName<E>& entry : names_of(E{}).names) names.emplace_back(entry.name);
    return names;
}

// "a|b|c" with "|", or "a, b or c" with ", " and " or ".
template <NamedEnum E>
std::string joined_names(std::string_view separator, std::string_view last_separator) {
    const std::vector<std::string> names = all_names<E>();
    std::string text;
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (i > 0) text += i + 1 == names.size() ? last_separator : separator;
        text += names[i];
    }
    return text;
}

template <NamedEnum E>
std::string joined_names(std::string_view separator = "|") {
    return joined_names<E>(separator, separator);
}

// The value of that name; any other text is an InputError: `--flag: expected a, b or c, got "x"`.
template <NamedEnum E>
E from_string(std::string_view text) {
    for (const EnumName<E>& entry : names_of(E{}).names)
        if (entry.name == text) return entry.value;
    throw InputError(std::string(names_of(E{}).flag) + ": expected " + joined_names<E>(", ", " or ") +
                     ", got \"" + printable(text, 64) + "\"");
}

}  // namespace rt
