#include "termination.hpp"

#include <algorithm>
#include <cmath>

namespace rt {

Real survival_probability(const TerminationSettings& settings, int depth, const Color& throughput) {
    // EXERCISE(ch05.termination) § Stopping the recursion
    if (depth >= settings.max_depth) return 0;
    if (!is_finite(throughput)) return 0;
    const Real largest = std::max({throughput.r, throughput.g, throughput.b});
    if (!(largest > 0)) return 0;  // a black path carries nothing, whatever the rule
    switch (settings.rule) {
        case Termination::kMaxDepth:
            return 1;
        case Termination::kMinThroughput:
            return largest >= settings.min_throughput ? Real(1) : Real(0);
        case Termination::kRussianRoulette:
            return depth < settings.roulette_start_depth ? Real(1) : std::min(Real(1), largest);
    }
    return 0;
    // END EXERCISE
}

bool continue_path(const TerminationSettings& settings, int depth, Color& throughput, Real u,
                   Real judged_scale) {
    const Real q = survival_probability(settings, depth, throughput * judged_scale);
    if (!(u < q)) return false;  // q = 0 always stops; q = 1 never does (u < 1)
    if (q < 1) throughput /= q;
    return true;
}

}  // namespace rt
