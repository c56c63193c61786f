// Chapter 08's flags: the tracer (forward, reverse or combined), the combined tracer's knobs, how forward
// paths reach the camera, and --forward-study with its options; each refused without the choice it serves.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "07_bsdf_refraction/bsdf_render.hpp"
#include "combined_render.hpp"
#include "forward_study.hpp"
#include "light_tracer.hpp"
#include "rt/core/enum_names.hpp"

namespace rt {

// What chapter 08 simulates: chapter 07's effects but shading normals. The light tracer's BSDF would need its
// adjoint for them (Veach 1997, 5.3): smooth meshes are shaded faceted here.
inline constexpr EffectSet kForwardChapterEffects =
    kRefractionChapterEffects.without({Effect::kShadingNormals});

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
