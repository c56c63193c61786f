#include "gi_notes.hpp"

#include "03_shadow_rays/environment_note.hpp"
#include "04_direct_lighting/bsdf.hpp"
#include "gi_render.hpp"
#include "rt/core/formatted.hpp"

namespace rt {
namespace {

// What the material table shades by a stand-in, and the lobes this chapter samples only uniformly.
std::vector<std::string> material_notes(const Scene& scene, const MaterialTable& materials,
                                        const EffectSet& simulated) {
    std::vector<std::string> notes = materials.notes();
    const std::vector<bool> used = scene.used_materials();
    for (std::size_t i = 0; i < scene.materials.size(); ++i) {
        if (!used[i]) continue;
        const Bsdf& bsdf = materials.bsdf(int(i));
        const std::string name = "material '" + scene.materials[i].name + "'";
        const bool lobe = !is_delta(bsdf) && !is_black(bsdf) && !bsdf.flags().diffuse;
        if (lobe && simulated.contains(Effect::kIndirect)) {
            notes.push_back(name +
                            ": its lobe reflects direct light (chapter 04) and indirect light from uniform "
                            "hemisphere directions, unbiased but noisy for a sharp lobe; chapter 06 samples "
                            "the lobe itself (BRDF sampling)");
        }
    }
    return notes;
}

}  // namespace

std::vector<std::string> gi_notes(const Scene& scene, const DirectLighting& shading,
                                  const TerminationSettings& termination, const RenderResult& result) {
    std::vector<std::string> notes = material_notes(scene, shading.materials(), shading.options().simulated);
    std::string rule = "termination: " + describe(termination);
    if (termination.rule == Termination::kMinThroughput ||
        termination.rule == Termination::kRussianRoulette) {
        rule += termination.rule == Termination::kMinThroughput ? ", biased" : ", unbiased below the cap";
    } else {
        rule +=
            formatted(", light after more than %.0f bounces is lost (biased)", double(termination.max_depth));
    }
    notes.push_back(rule);
    if (shading.lights().empty()) notes.push_back("the scene has no light: no direct light, no shadow rays");
    if (const auto note = environment_image_note(shading.lights().environment)) notes.push_back(*note);
    for (const std::string& u : shading.lights().unsampled) {
        notes.push_back("emitter not sampled as a light: " + u + "; indirect rays count its emission");
    }
    if (!shading.options().simulates(Effect::kDirect)) {
        notes.push_back("the effect direct is off: no light sampling; indirect rays count every emitter");
    }
    const double camera_rays = double(result.rays[RayKind::kCamera]);
    if (camera_rays > 0) {
        notes.push_back(
            formatted("per camera ray: %.3f reflection rays, %.3f indirect rays, %.3f shadow rays",
                      double(result.rays[RayKind::kReflection]) / camera_rays,
                      double(result.rays[RayKind::kIndirect]) / camera_rays,
                      double(result.rays[RayKind::kShadow]) / camera_rays));
    }
    return notes;
}

std::string furnace_note(const Furnace& furnace, const TerminationSettings& termination, bool indirect) {
    const Vec3d exact = furnace_radiance(furnace);
    std::string note = formatted("furnace: exact L = Le / (1 - rho) = %.6g", exact.y);
    if (termination.rule != Termination::kMinThroughput && indirect) {
        note += formatted("; this rule's expected value Le (1 - rho^(N+1)) / (1 - rho) = %.6g with N = %.0f",
                          furnace_radiance_truncated(furnace, termination.max_depth).y,
                          double(termination.max_depth));
    }
    return note + " (green channel)";
}

}  // namespace rt
