// What every tracer of the course reads from the run, in one value: the effects it simulates and how its rays
// leave surfaces. A tracer asks `simulates(Effect::kShadows)` instead of keeping a boolean of its own, so the
// mapping from the simulated effects to what a tracer does is written once, here. Each chapter's options
// extend it with that chapter's own knobs (samples per light, sampling strategy, termination, ...).
#pragma once

#include "03_shadow_rays/ray_offset.hpp"
#include "quad_light_strategy.hpp"
#include "rt/core/effect_set.hpp"

namespace rt {

struct TraceOptions {
    EffectSet simulated = EffectSet::all();
    RayOffset offset{};
    QuadLightSampling quad_lights = QuadLightSampling::kArea;  // how quad lights are sampled (--quad-lights)

    bool simulates(Effect effect) const { return simulated.contains(effect); }
};

}  // namespace rt
