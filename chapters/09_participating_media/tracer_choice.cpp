#include "tracer_choice.hpp"

#include "07_bsdf_refraction/refraction_materials.hpp"
#include "08_forward_tracing/combined_render.hpp"
#include "08_forward_tracing/forward_notes.hpp"
#include "media_notes.hpp"
#include "rt/core/errors.hpp"

namespace rt {

namespace {

// Whether a material the scene uses is a mirror or smooth glass: where caustics start.
bool has_delta_surface(const Scene& scene, const EffectSet& simulated) {
    const MaterialTable materials(scene, simulated, refraction_materials());
    const std::vector<bool> used = scene.used_materials();
    for (std::size_t m = 0; m < materials.size(); ++m) {
        if (used[m] && (is_delta(materials.bsdf(int(m), true)) || is_delta(materials.bsdf(int(m), false))))
            return true;
    }
    return false;
}

}  // namespace

TracerChoice choose_tracer(TracerRule rule, const RunContext& context, GivenFlags given) {
    const Scene& scene = context.scene;
    const EffectSet& simulated = context.simulated;
    const auto chosen = [](bool combined, std::string why) {
        TracerChoice choice;
        choice.combined = combined;
        choice.because = std::move(why);
        return choice;
    };
    const auto paths = [&](std::string why) { return chosen(false, std::move(why)); };
    if (rule == TracerRule::kPaths) return paths("--tracer paths asks for them");
    if (choose_renderer(simulated) == Renderer::kDirect)
        return paths("the scene calls for direct light only");
    if (simulated.contains(Effect::kMedia)) {
        TracerChoice choice = paths("light paths cross no medium (chapter 08)");
        // Fog, between the shapes: its points lie anywhere, beside a lamp too. Inside a shape (a walk) the
        // shape's boundary mostly stands between a point and the lamp, and the flags' own defaults serve.
        if (!scene.medium || !scene.medium->scatters()) return choice;
        std::string sampling;
        if (!given.distance_sampling) {
            choice.distance = DistanceSampling::kMis;
            sampling = "equiangular points by MIS";
        }
        if (!given.quad_lights) {
            choice.quad_lights = QuadLightSampling::kSolidAngle;
            sampling += std::string(sampling.empty() ? "" : " and ") + "quad lights by solid angle";
        }
        if (!sampling.empty()) choice.because += "; in the fog, " + sampling + ", as Cycles samples volumes";
        return choice;
    }
    if (given.termination)
        return paths("a depth or a termination rule is set, and light paths count bounces from the light");
    if (!has_delta_surface(scene, simulated))
        return paths("no mirror or smooth glass: no caustic for light paths to find");
    const LightSet lights = collect_lights(scene);
    if (lights.environment || !lights.unsampled.empty())
        return paths("light paths start only at area and point lights, and this scene has other light");
    if (simulated.contains(Effect::kShadingNormals))
        return paths("the light tracer would shade the smooth meshes faceted (chapter 08)");
    if (scene.camera.aperture > 0) return paths("light paths reach a pinhole, and this camera has a lens");
    // A piece would be rendered otherwise than the whole, and the pieces must merge into the whole's bits.
    if (context.settings.samples || context.settings.resume) {
        throw InputError(std::string(context.settings.resume ? "--resume" : "--samples (or MPI ranks)") +
                         ": this scene's caustics are rendered by the combined tracer, which renders whole; "
                         "--tracer paths renders in pieces");
    }
    return chosen(true,
                  "mirrors or smooth glass lit by area or point lights: light paths find the caustics "
                  "the camera sees (chapter 08)");
}

ChapterRun render_by_choice(TracerRule rule, const RunContext& context, PathOptions options, MediumWalk walk,
                            GivenFlags given) {
    const TracerChoice choice = choose_tracer(rule, context, given);
    options.simulated = context.simulated;
    if (choice.distance) walk.distance = *choice.distance;
    if (choice.quad_lights) options.quad_lights = *choice.quad_lights;
    ChapterRun run;
    if (choice.combined) {
        CombinedOptions combined;
        combined.paths = options;
        const CombinedResult r =
            render_combined(context.scene, context.simulated, context.settings, combined);
        run = {r.render, combined_notes(context.scene, context.simulated, combined, r), std::nullopt};
    } else {
        const Renderer renderer = choose_renderer(context.simulated);
        run = {render_with_media(renderer, context.scene, context.simulated, context.settings, options, walk),
               media_notes(context.scene, renderer, options, walk), std::nullopt};
    }
    run.notes.insert(run.notes.begin(), std::string("strategy: ") + (choice.combined ? "combined" : "paths") +
                                            ", because " + choice.because);
    return run;
}

}  // namespace rt
