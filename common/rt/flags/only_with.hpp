// A flag that matters only with another is refused without it, so that no flag is ever silently ignored: a
// study's options without the study, --epsilon without --offset epsilon. The rule is declared where the
// flag is added, as one more check of its value:
//     app.add_option("--csv", csv, "With --aa-study: ...")->check(only_with({{study}}));
//     app.add_option("--epsilon", epsilon, "...")->check(only_with({{offset, {"epsilon"}}}));
// CLI11 runs it once the whole command line is read, so a refusal is a usage error (exit 2) before anything
// renders, and the live view's changes, parsed by the same CLI::App, are checked alike.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace rt {

// `flag` given (values empty), or `flag`'s value, the one given last or else its default, one of `values`.
struct FlagCondition {
    const CLI::Option* flag;
    std::vector<std::string> values = {};
};

// The check of a flag that matters only when one of `any_of` holds. Its message names both flags:
// "only with --offset epsilon, got --offset robust".
CLI::Validator only_with(std::vector<FlagCondition> any_of);

}  // namespace rt
