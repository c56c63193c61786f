#include "termination_flags.hpp"

#include "rt/flags/enum_flag.hpp"

namespace rt {

TerminationSettings TerminationFlags::resolved() const {
    TerminationSettings out = settings;
    // Roulette and the throughput rule end paths themselves; the cap then only guards against a path between
    // two mirrors, high enough not to bias the result measurably.
    out.max_depth = max_depth.value_or(settings.rule == Termination::kMaxDepth ? 8 : kSafetyDepthCap);
    return out;
}

CLI::Option* add_termination_flags(CLI::App& app, TerminationFlags& flags) {
    CLI::Option* rule =
        add_enum_option(app, flags.settings.rule,
                        "When a path stops: depth (after --max-depth bounces), throughput (when "
                        "max(throughput) falls below a threshold) or roulette (Russian "
                        "roulette, unbiased)");
    app.add_option("--max-depth", flags.max_depth,
                   "Bounces after the camera ray: the depth rule's N (default 8), a hard cap for the others "
                   "(default 64)")
        ->check(CLI::Range(1, 1024));
    return rule;
}

}  // namespace rt
