#include "forward_notes.hpp"

#include <algorithm>
#include <cstdio>
#include <string_view>

#include "07_bsdf_refraction/refraction_materials.hpp"
#include "light_emission.hpp"

namespace rt {
namespace {

std::vector<std::string> scene_notes(const Scene& scene, const MaterialTable& materials,
                                     const LightSet& lights, bool forward) {
    std::vector<std::string> notes = materials.notes();
    const std::vector<bool> used = scene.used_materials();
    for (std::size_t i = 0; i < materials.size() && forward; ++i) {
        const Bsdf& bsdf = materials.bsdf(int(i));
        if (used[i] && is_delta(bsdf) && !is_black(bsdf)) {
            notes.push_back("material '" + scene.materials[i].name +
                            "': a delta BSDF (mirror or smooth glass): a pinhole cannot be connected to its "
                            "vertices, so the light tracer shows it black (what it reflects or refracts is "
                            "lost); the caustics it casts are found");
        }
    }
    if (forward && lights.environment) {
        notes.push_back("the environment light is not traced forward (no light paths start from it): black");
    }
    // One note per kind, in the lights' order: a delta light is never seen; a kind not traced forward lights
    // nothing here.
    std::vector<std::string_view> noted;
    for (const auto& light : lights.lights) {
        const std::string_view kind = light->kind();
        if (!forward || std::find(noted.begin(), noted.end(), kind) != noted.end()) continue;
        noted.push_back(kind);
        if (!traced_forward(*light)) {
            notes.push_back(std::string(kind) +
                            " lights are not traced forward (no light paths start from them): "
                            "what only they light is black");
        } else if (light->is_delta()) {
            notes.push_back(std::string(kind) +
                            " lights light the scene but are not seen themselves (as in every chapter)");
        }
    }
    for (const std::string& u : lights.unsampled) notes.push_back("emitter not sampled as a light: " + u);
    return notes;
}

// The percentage of `paths` that reached the camera.
double reached(std::uint64_t contributing, std::uint64_t paths) {
    return 100.0 * double(contributing) / double(std::max<std::uint64_t>(1, paths));
}

}  // namespace

std::vector<std::string> forward_notes(const RenderScene& prepared, const LightTracerOptions& options,
                                       const SplatResult& result) {
    std::vector<std::string> notes = scene_notes(prepared.scene, prepared.materials, prepared.lights, true);
    char line[200];
    std::snprintf(line, sizeof line,
                  "tracer: forward, variant %s; %llu light paths (spp x pixels), %.4g%% of them reached the "
                  "camera",
                  to_string(options.variant).data(), static_cast<unsigned long long>(result.render.samples),
                  reached(result.contributing_paths, result.render.samples));
    notes.push_back(line);
    notes.push_back(
        "rays: light-to-surface rays counted as shadow, connections to the camera as camera rays");
    return notes;
}

std::vector<std::string> reverse_notes(const Scene& scene, const EffectSet& simulated, Renderer renderer) {
    std::vector<std::string> notes = scene_notes(
        scene, MaterialTable(scene, simulated, refraction_materials()), collect_lights(scene), false);
    notes.push_back("tracer: reverse, chapter 07's renderer: " + std::string(to_string(renderer)));
    return notes;
}

std::vector<std::string> combined_notes(const Scene& scene, const EffectSet& simulated,
                                        const CombinedOptions& options, const CombinedResult& result) {
    std::vector<std::string> notes = scene_notes(
        scene, MaterialTable(scene, simulated, refraction_materials()), collect_lights(scene), false);
    const char* sampler = to_string(options.paths.sampler).data();
    char line[320];
    if (result.split) {
        std::snprintf(line, sizeof line,
                      "tracer: combined; chapter 06's paths (sampler %s, %.3f s) for all paths but "
                      "E D{1..%d} S ... (the caustics the camera sees), %llu light paths for those "
                      "(%.3f s, %.4g%% reached the camera)",
                      sampler, result.paths.seconds, options.caustic_bounces,
                      static_cast<unsigned long long>(result.caustics.render.samples),
                      result.caustics.render.seconds,
                      reached(result.caustics.contributing_paths, result.caustics.render.samples));
    } else {
        std::snprintf(line, sizeof line,
                      "tracer: combined, by chapter 06's paths alone (sampler %s): light paths start "
                      "only at area and point lights and cross no medium, and this scene has other "
                      "light or a medium",
                      sampler);
    }
    notes.push_back(line);
    notes.push_back(
        "rays: light paths' first rays counted as shadow, connections to the camera as camera rays");
    return notes;
}

}  // namespace rt
