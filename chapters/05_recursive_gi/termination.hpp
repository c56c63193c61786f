// When a recursive trace stops. Each bounce multiplies the path's throughput β (the product of f cos θ / p
// along it) into everything that follows, so a path can be cut short three ways:
//  - max depth:      stop after N bounces. Light that bounced more than N times is lost: biased low, by
//                    Le ρ^(N+1) / (1 − ρ) in a furnace of albedo ρ.
//  - min throughput: stop when max(β) < β_min ("too dim to matter"). Still biased: the dim paths it drops
//                    carried light, and many dim paths add up.
//  - Russian roulette: from bounce d₀ on, go on with a probability q that falls with max(β), and weight a
//                    survivor so that the mean weight E[β'] over surviving and stopping is β: unbiased.
// max_depth is a hard cap for every rule, so a path between two perfect mirrors ends too.
#pragma once

#include "rt/core/enum_names.hpp"
#include "rt/core/math.hpp"

namespace rt {

enum class Termination { kMaxDepth, kMinThroughput, kRussianRoulette };

constexpr auto names_of(Termination) {
    return enum_names<Termination>("--termination", {{Termination::kMaxDepth, "depth"},
                                                     {Termination::kMinThroughput, "throughput"},
                                                     {Termination::kRussianRoulette, "roulette"}});
}

struct TerminationSettings {
    Termination rule = Termination::kRussianRoulette;
    int max_depth = 8;  // kMaxDepth: bounces after the camera ray; also a hard cap for the others
    Real min_throughput = Real(0.01);  // kMinThroughput: stop when max component of throughput falls below it
    int roulette_start_depth = 3;      // kRussianRoulette: bounces before roulette starts

    bool operator==(const TerminationSettings&) const = default;
};

// The hard cap this course gives the rules that end paths by themselves (throughput and roulette), so that
// the cap does not bias them measurably: a furnace of albedo 0.8 (L = 5 Le) loses Le 0.8^65 / 0.2 ≈ 2.5e-6
// Le.
inline constexpr int kSafetyDepthCap = 64;

// The probability q that a path with throughput β at `depth` (bounces made so far) bounces on:
// 0 at or past max_depth, or when β is zero or not finite; otherwise max depth: 1; min throughput: 1 if
// max(β) >= β_min, else 0; Russian roulette: 1 before roulette_start_depth, then the probability for which
// a survivor's largest channel is weighted up to exactly 1, and a path of max(β) >= 1 always goes on.
Real survival_probability(const TerminationSettings& settings, int depth, const Color& throughput);

// Whether a path at `depth` bounces on: it goes on when u < q (q from survival_probability; `u` a uniform
// random number in [0, 1)), and a survivor's throughput is then rescaled so that E[β'] = β.
// q is judged on throughput × `judged_scale` (chapter 06's path loop hands in the η² of the glass a path is
// in, PBRT's η-scale, so that refraction's 1/η² does not end paths inside glass sooner); any q > 0 keeps the
// estimate unbiased, E[β'] = β.
bool continue_path(const TerminationSettings& settings, int depth, Color& throughput, Real u,
                   Real judged_scale = 1);

}  // namespace rt
