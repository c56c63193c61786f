#include "monte_carlo_notes.hpp"

namespace rt {

std::vector<std::string> monte_carlo_notes(const RenderScene& prepared, const PathOptions& options) {
    std::vector<std::string> notes = prepared.materials.notes();
    if (prepared.scene.has_delta_lights()) {
        notes.push_back(
            "point, distant and spot lights are deltas: only the light and mis strategies see them (no "
            "sampled "
            "direction hits them)");
    }
    notes.push_back("sampling: " + std::string(to_string(options.strategy)) +
                    ", quad lights: " + std::string(to_string(options.quad_lights)) +
                    ", sampler: " + std::string(to_string(options.sampler)) +
                    ", termination: " + std::string(to_string(options.termination.rule)));
    if (const auto& sky = prepared.scene.environment; sky && sky->image) {
        notes.push_back("environment image " + sky->image_file + " (" + std::to_string(sky->image->width()) + "x" +
                        std::to_string(sky->image->height()) + ", latitude-longitude): " +
                        (samples_lights(options.strategy)
                             ? "light samples drawn by its 2-D distribution (luminance x sin theta)"
                             : "found only by the directions the strategy draws"));
    }
    for (const std::string& u : prepared.lights.unsampled)
        notes.push_back("emitter not sampled as a light: " + u);
    return notes;
}

}  // namespace rt
