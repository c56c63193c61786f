#include "refraction_notes.hpp"

#include "05_recursive_gi/gi_render.hpp"
#include "refraction_materials.hpp"

namespace rt {

std::vector<std::string> refraction_notes(const Scene& scene, Renderer renderer, const PathOptions& options) {
    std::vector<std::string> notes{"renderer: " + std::string(to_string(renderer))};
    const MaterialTable materials(scene, options.simulated, refraction_materials());
    for (const std::string& note : materials.notes()) notes.push_back(note);
    notes.push_back("sampling: " + std::string(to_string(options.strategy)) +
                    ", quad lights: " + std::string(to_string(options.quad_lights)) +
                    ", sampler: " + std::string(to_string(options.sampler)) +
                    ", termination: " + describe(options.termination));
    return notes;
}

}  // namespace rt
