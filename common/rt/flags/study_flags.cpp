#include "rt/flags/study_flags.hpp"

namespace rt::detail {

std::string study_help(const StudyOption& option, const std::vector<FlagCondition>& studies,
                       std::string help) {
    if (!help.empty() || studies.empty()) return help;
    return "With " + studies.front().flag->get_name() + ": " + option.help;
}

}  // namespace rt::detail
