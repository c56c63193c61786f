#include "rt/flags/only_with.hpp"

#include <algorithm>

namespace rt {
namespace {

// A flag's value as the run will use it: the last one given, else its default.
std::string value_of(const CLI::Option& flag) {
    return flag.count() > 0 && !flag.results().empty() ? flag.results().back() : flag.get_default_str();
}

bool holds(const FlagCondition& c) {
    if (c.values.empty()) return c.flag->count() > 0;
    return std::find(c.values.begin(), c.values.end(), value_of(*c.flag)) != c.values.end();
}

// "--offset epsilon", "--denoiser bilateral or atrous", "--offset-study".
std::string describe(const FlagCondition& c) {
    std::string text = c.flag->get_name();
    for (std::size_t i = 0; i < c.values.size(); ++i) text += (i == 0 ? " " : " or ") + c.values[i];
    return text;
}

}  // namespace

CLI::Validator only_with(std::vector<FlagCondition> any_of) {
    auto check = [any_of](const std::string&) -> std::string {
        if (std::any_of(any_of.begin(), any_of.end(), holds)) return "";
        std::string message = "only with ";
        std::string got;
        for (std::size_t i = 0; i < any_of.size(); ++i) {
            message += (i == 0 ? "" : " or ") + describe(any_of[i]);
            if (!any_of[i].values.empty())
                got += (got.empty() ? "" : ", ") + any_of[i].flag->get_name() + " " + value_of(*any_of[i].flag);
        }
        return got.empty() ? message : message + ", got " + got;
    };
    return CLI::Validator(check, "");
}

}  // namespace rt
