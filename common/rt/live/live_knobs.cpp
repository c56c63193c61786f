#include "rt/live/live_knobs.hpp"

#include <algorithm>

#include "rt/core/errors.hpp"
#include "rt/core/printable.hpp"

namespace rt {
namespace {

// A demo mode's own option: its help starts "With --FLAG" (then ':' or ' '), FLAG an option taking no value.
bool belongs_to_a_mode(const CLI::App& app, const CLI::Option& option) {
    const std::string& help = option.get_description();
    if (!help.starts_with("With --")) return false;
    const std::size_t end = help.find_first_of(": ", 5);
    const std::string mode = help.substr(5, end == std::string::npos ? std::string::npos : end - 5);
    for (const CLI::Option* other : app.get_options()) {
        if (other->get_name() == mode) return other->get_items_expected_max() == 0;
    }
    return false;
}

// The allowed values of an option checked by CLI::IsMember, whose type name then holds "{a,b,c}".
std::vector<std::string> choices_of(const CLI::Option& option) {
    const std::string type = option.get_type_name();
    const std::size_t open = type.find('{'), close = type.find('}', open);
    std::vector<std::string> choices;
    if (open == std::string::npos || close == std::string::npos) return choices;
    std::string item;
    for (std::size_t i = open + 1; i <= close; ++i) {
        if (type[i] == ',' || i == close) {
            choices.push_back(item);
            item.clear();
        } else {
            item += type[i];
        }
    }
    return choices;
}

}  // namespace

LiveKnobs::LiveKnobs(CLI::App& app, const std::set<std::string>& core, std::vector<std::string> args)
    : app_(app), args_(std::move(args)) {
    for (CLI::Option* option : app_.get_options()) {
        const std::string name = option->get_name();
        // A live run writes nothing: an option that writes a file (its help starts "Write", as chapter 02's
        // --write-mesh) is no knob either.
        if (core.contains(name) || option->get_items_expected_max() != 1 || belongs_to_a_mode(app_, *option) ||
            option->get_description().starts_with("Write"))
            continue;
        // A knob set live is given again after the command line: the last of its values counts.
        option->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
        knobs_.push_back(Knob{name, option->get_description(), choices_of(*option), ""});
    }
    previous_args_ = args_;
    read_values();
}

bool LiveKnobs::has(const std::string& name) const {
    return std::any_of(knobs_.begin(), knobs_.end(), [&](const Knob& k) { return k.name == name; });
}

void LiveKnobs::parse(const std::vector<std::string>& args) {
    // CLI11 takes a vector of arguments last first.
    std::vector<std::string> reversed(args.rbegin(), args.rend());
    app_.parse(reversed);
}

void LiveKnobs::read_values() {
    for (Knob& knob : knobs_) {
        const CLI::Option* option = app_.get_option(knob.name);
        knob.value = option->count() > 0 ? option->results().back() : option->get_default_str();
    }
}

void LiveKnobs::set(const std::string& name, const std::string& value) {
    if (!has(name)) throw InputError("no knob " + name);
    // A command line cannot hold a NUL byte, and CLI11's message would end at it (quoting "mis" for "mis\0x").
    if (value.find('\0') != std::string::npos)
        throw InputError("usage: " + name + ": a value holds no NUL byte, got \"" + printable(value, 64) + "\"");
    std::vector<std::string> args = args_;
    args.push_back(name + "=" + value);
    try {
        parse(args);
    } catch (const CLI::ParseError& e) {
        // A check after the values were stored (a chapter's parse_complete_callback) may have changed some:
        // the command line that was accepted last sets them back.
        parse(args_);
        throw InputError(std::string("usage: ") + e.what() + " (see --help)");
    }
    previous_args_ = args_;
    args_ = std::move(args);
    read_values();
}

void LiveKnobs::undo() {
    args_ = previous_args_;
    parse(args_);
    read_values();
}

}  // namespace rt
