#include "media_notes.hpp"

#include "media_materials.hpp"

namespace rt {

std::vector<std::string> media_notes(const Scene& scene, Renderer renderer, const PathOptions& options,
                                     const MediumWalk& walk) {
    std::vector<std::string> notes{
        renderer == Renderer::kDirect ? std::string(to_string(renderer))
        : options.simulated.contains(Effect::kMedia)
            ? "renderer: paths (chapter 09's volumetric loop, chapter 07's BSDFs)"
            : "renderer: paths (chapter 07's loop: the scene calls for no media)"};
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
    return notes;
}

}  // namespace rt
