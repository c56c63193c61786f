// Chapter 08's flags: the tracer (forward, reverse or combined), the combined tracer's knobs, how forward
// paths reach the camera, and --forward-study with its options; each refused without the choice it serves.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "combined_render.hpp"
#include "forward_study.hpp"
#include "light_tracer.hpp"
#include "rt/core/enum_names.hpp"

namespace rt {

enum class Tracer { kForward, kReverse, kCombined };

constexpr auto names_of(Tracer) {
    return enum_names<Tracer>(
        "--tracer",
        {{Tracer::kForward, "forward"}, {Tracer::kReverse, "reverse"}, {Tracer::kCombined, "combined"}});
}

struct ForwardFlags {
    Tracer tracer = Tracer::kForward;
    CombinedOptions combined;
    CameraVariant variant = CameraVariant::kConnect;
    Real aperture = 1;
    bool caustics_only = false;
    bool study = false;
    StudyOptions study_options;

    // The forward tracer's options, simulating `simulated`.
    LightTracerOptions light_tracer(const EffectSet& simulated) const;
    // Why the render cannot be split into pieces with this tracer ("" when it can).
    std::string renders_whole_because() const;
};

void add_forward_flags(CLI::App& app, ForwardFlags& flags);

}  // namespace rt
