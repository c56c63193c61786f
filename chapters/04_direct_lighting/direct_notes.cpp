#include "direct_notes.hpp"

#include <string_view>
#include <utility>
#include <vector>

#include "03_shadow_rays/environment_note.hpp"

namespace rt {
namespace {

// "1 quad", "2 quads".
std::string count_text(std::size_t n, const std::string& what) {
    return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
}

// "7 quads, 1 sphere, 2 points": the lights counted by kind, in their order.
std::string kinds_text(const LightSet& lights) {
    std::vector<std::pair<std::string_view, std::size_t>> counts;
    for (const auto& light : lights.lights) {
        if (counts.empty() || counts.back().first != light->kind()) counts.emplace_back(light->kind(), 0);
        ++counts.back().second;
    }
    std::string text;
    for (const auto& [kind, n] : counts)
        text += (text.empty() ? "" : ", ") + count_text(n, std::string(kind));
    return text;
}

std::string lights_note(const DirectLighting& shading, const DirectOptions& options) {
    const LightSet& sampled = shading.lights();
    if (sampled.empty()) return "the scene has no light to sample: no direct light, no shadow rays";
    const std::string kinds = kinds_text(sampled);
    return "lights: " + kinds +
           (sampled.environment ? std::string(kinds.empty() ? "" : ", ") + "an environment" : "") +
           " (quads sampled by " + std::string(to_string(options.quad_lights)) + "); " +
           count_text(std::size_t(options.shadow_samples), "shadow sample") +
           (shading.picks_lights() ? " per hit, each from a light picked by power, "
                                   : " per light per hit, ") +
           std::string(to_string(options.light_sampler));
}

}  // namespace

std::vector<std::string> direct_notes(const MaterialTable& materials, const DirectLighting& shading,
                                      const DirectOptions& options, bool analytic) {
    std::vector<std::string> notes = materials.notes();
    for (const std::string& u : shading.lights().unsampled)
        notes.push_back("emitter not sampled as a light: " + u);
    notes.push_back(lights_note(shading, options));
    if (const auto note = environment_image_note(shading.lights().environment)) notes.push_back(*note);
    if (analytic) {
        notes.push_back(
            "analytic scene (a diffuse plane under one quad light): rays through pixel centres, compared "
            "with "
            "rho/pi * E from Lambert's polygon formula");
    }
    return notes;
}

}  // namespace rt
