// The options the chapters' studies share, declared here once: the table they write (--csv), the folder of
// their cached converged references (--cache) and those references' samples per pixel (--reference-spp).
// Each is refused without a study that uses it (only_with.hpp), and its help says which: "With --converge:
// spp of the reference".
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <utility>
#include <vector>

#include "rt/flags/only_with.hpp"

namespace rt {

struct StudyOption {
    const char* name;
    const char* help;  // what it is, after "With --study: "
};

inline constexpr StudyOption kCsvOption{"--csv", "also write the table as CSV"};
inline constexpr StudyOption kCacheOption{"--cache", "folder of the cached reference PFM"};
inline constexpr StudyOption kReferenceSppOption{"--reference-spp", "spp of the reference"};
inline constexpr int kMostReferenceSpp = 1 << 20;

namespace detail {
// "With --first-study: " and the option's own words, or `help` whole where the chapter says more.
std::string study_help(const StudyOption& option, const std::vector<FlagCondition>& studies,
                       std::string help);
}  // namespace detail

// `option` into `value`, refused without one of `studies` (checked after `checks`, as a study's own checks
// come first).
template <class T>
CLI::Option* add_study_option(CLI::App& app, const StudyOption& option, T& value,
                              std::vector<FlagCondition> studies, std::string help = {},
                              const std::vector<CLI::Validator>& checks = {}) {
    CLI::Option* added =
        app.add_option(option.name, value, detail::study_help(option, studies, std::move(help)));
    for (const CLI::Validator& check : checks) added->check(check);
    return added->check(only_with(std::move(studies)));
}

// --reference-spp into `spp`: from `fewest` to kMostReferenceSpp.
inline CLI::Option* add_reference_spp_option(CLI::App& app, int& spp, int fewest,
                                             std::vector<FlagCondition> studies, std::string help = {}) {
    return add_study_option(app, kReferenceSppOption, spp, std::move(studies), std::move(help),
                            {CLI::Range(fewest, kMostReferenceSpp)});
}

}  // namespace rt
