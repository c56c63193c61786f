// A flag whose value is one of an enum's names (enum_names.hpp): the check, the choices and the option.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "rt/core/enum_names.hpp"

namespace rt {

// The command line's check that a value is one of the names (the live view lists them as the choices).
template <NamedEnum E>
CLI::Validator choices() {
    return CLI::IsMember(all_names<E>());
}

// The flag names_of(E) names, taking one of the names into `value`; --help shows its current name as the
// default.
template <NamedEnum E>
CLI::Option* add_enum_option(CLI::App& app, E& value, const std::string& help) {
    CLI::Option* option = app.add_option_function<std::string>(
        std::string(names_of(value).flag),
        [&value](const std::string& name) { value = from_string<E>(name); }, help);
    return option->check(choices<E>())->default_str(std::string(to_string(value)));
}

}  // namespace rt
