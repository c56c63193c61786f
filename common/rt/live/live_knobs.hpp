// The chapter's knobs for the live view (live_view.hpp): its own flags that take one value, read from its
// CLI11 options (name, help, choices, current value), and changed as the command line would change them.
#pragma once

#include <CLI/CLI.hpp>
#include <set>
#include <string>
#include <vector>

namespace rt {

struct Knob {
    std::string name;                  // "--sampling"
    std::string help;                  // the flag's --help text
    std::vector<std::string> choices;  // its allowed values when it has a list of them (CLI::IsMember)
    std::string value;                 // as given, or its default ("" when it has none)
};

class LiveKnobs {
public:
    // The knobs of `app`, parsed from `args` (the command line without the program's name): every option not
    // in `core` that takes one value, but for a demo mode's own options (their help starts "With --FLAG:",
    // FLAG a flag that takes no value, as "With --converge: the largest spp") and options that write a file
    // (their help starts "Write").
    LiveKnobs(CLI::App& app, const std::set<std::string>& core, std::vector<std::string> args);

    const std::vector<Knob>& knobs() const { return knobs_; }
    bool has(const std::string& name) const;

    // Sets knob `name` to `value` as `--name=value` after the command line would: the whole command line is
    // parsed again with it. When the command line would refuse it, throws InputError with the message the
    // run would print ("usage: --sampling: ... (see --help)"), and the line accepted last is parsed again.
    // (CLI11 leaves a flag's variable alone when the flag is not given, so what that restores is the value
    // of every flag given so far; a value stored before a later check refused it, as chapter 08's
    // --aperture without --variant aperture, stays in a flag never given, which that check then ignores.)
    void set(const std::string& name, const std::string& value);
    // Takes back the last set() (the render refused what it allowed), as a refusal does.
    void undo();

private:
    void parse(const std::vector<std::string>& args);
    void read_values();

    CLI::App& app_;
    std::vector<std::string> args_;
    std::vector<std::string> previous_args_;
    std::vector<Knob> knobs_;
};

}  // namespace rt
