// Chapter 04's renders: each sample traces one camera ray and adds the emission and the direct light at its
// hit; and the study of shadow samples against error and time on the analytic scene.
#pragma once

#include <vector>

#include "01_ray_generation/camera.hpp"
#include "analytic_scene.hpp"
#include "direct_lighting.hpp"
#include "rt/core/effect_set.hpp"
#include "rt/render/render_loop.hpp"

namespace rt {

// What chapter 04 simulates: chapter 03's point lights and shadows, area lights and the environment, and the
// glossy lobes, and a smooth mesh's shading normals.
inline constexpr EffectSet kDirectChapterEffects{Effect::kCameraRays, Effect::kShadows, Effect::kDirect,
                                                 Effect::kGlossy, Effect::kShadingNormals};

// Where a pixel's camera rays pass: stratified jitter (anti-aliased), or the pixel centre (for comparing
// with an exact image computed at the centres).
enum class FilmPoints { kStratified, kCentre };

RenderResult render_direct(const DirectLighting& shading, const PinholeCamera& camera,
                           const RenderSettings& settings, FilmPoints film_points);

struct ShadowStudyRow {
    LightSampler sampler;
    int shadow_samples;  // per pixel (one camera ray per pixel, so also per hit)
    double rmse;         // against the exact image
    double relative_mse;
    double mean_error;  // the bias: ≈ 0 for an unbiased estimator
    double seconds;     // render time
    std::uint64_t shadow_rays;
};

// The analytic scene at 1 sample per pixel (pixel centres) with N shadow samples, for each sampler and N.
std::vector<ShadowStudyRow> shadow_study(const World& world, const MaterialTable& materials,
                                         const LightSet& lights, DirectOptions options,
                                         const PinholeCamera& camera, RenderSettings settings,
                                         const Image& exact, const std::vector<LightSampler>& samplers,
                                         const std::vector<int>& shadow_samples);

}  // namespace rt
