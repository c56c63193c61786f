#include "media_notes.hpp"

#include "media_materials.hpp"

namespace rt {

namespace {

// Which loop renders: this chapter's only where the run simulates media (render_with_media).
std::string renderer_note(Renderer renderer, const EffectSet& simulated) {
    if (renderer == Renderer::kDirect) return std::string(to_string(renderer));
    if (simulated.contains(Effect::kMedia))
        return "renderer: paths (chapter 09's volumetric loop, chapter 07's BSDFs)";
    return "renderer: paths (chapter 06's loop, chapter 07's BSDFs: the scene calls for no media)";
}

}  // namespace

std::string environment_behind_fog_note(const Scene& scene, const EffectSet& simulated) {
    if (!simulated.contains(Effect::kMedia) || !scene.environment || !scene.medium) return "";
    const Color sigma_t = scene.medium->sigma_t();
    std::string channels;
    for (int c = 0; c < 3; ++c) {
        if (sigma_t[c] > 0) channels += std::string(channels.empty() ? "" : ", ") + "rgb"[c];
    }
    if (channels.empty()) return "";
    return "environment: none of its light arrives in " + channels +
           ": the fog (top-level medium) fills all space, and light from infinitely far is extinguished "
           "wherever sigma_a + sigma_s > 0";
}

std::vector<std::string> media_notes(const Scene& scene, Renderer renderer, const PathOptions& options,
                                     const MediumWalk& walk) {
    std::vector<std::string> notes{renderer_note(renderer, options.simulated)};
    const MaterialTable materials(scene, options.simulated, media_materials());
    for (const std::string& note : materials.notes()) notes.push_back(note);
    notes.push_back("sampling: " + std::string(to_string(options.strategy)) +
                    ", quad lights: " + std::string(to_string(options.quad_lights)) + ", walk: at most " +
                    std::to_string(walk.max_events) + " scattering events, roulette " +
                    (walk.roulette ? "on" : "off") +
                    ", distance sampling: " + std::string(to_string(walk.distance)) +
                    (walk.distance == DistanceSampling::kFreeFlight
                         ? ""
                         : " (on grey media's segments that end at a surface; others keep free flight)"));
    if (std::string fog = environment_behind_fog_note(scene, options.simulated); !fog.empty())
        notes.push_back(std::move(fog));
    return notes;
}

}  // namespace rt
