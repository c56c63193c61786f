#include "termination_flags.hpp"

#include "rt/flags/enum_flag.hpp"

namespace rt {

TerminationSettings TerminationFlags::resolved(const Scene& scene) const {
    TerminationSettings out = settings;
    // Roulette and the throughput rule end paths themselves; the cap then only guards against a path between
    // two mirrors, high enough not to bias the result measurably.
    const int own = settings.rule == Termination::kMaxDepth ? 8 : kSafetyDepthCap;
    out.max_depth = max_depth.value_or(scene.max_depth.value_or(own));
    return out;
}

CLI::Option* add_termination_flags(CLI::App& app, TerminationFlags& flags) {
    CLI::Option* rule =
        add_enum_option(app, flags.settings.rule,
                        "When a path stops: depth (after --max-depth bounces), throughput (when "
                        "max(throughput) falls below a threshold) or roulette (Russian "
                        "roulette, unbiased)");
    app.add_option("--max-depth", flags.max_depth,
                   "Bounces after the camera ray: the depth rule's N, a cap for the others (default: the "
                   "scene's max_depth, else 8 for the depth rule, 64 for the others)")
        ->check(CLI::Range(1, kMaxPathDepth));
    return rule;
}

}  // namespace rt
