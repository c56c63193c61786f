// A guided render: training passes of 1, 2, 4, … samples per pixel, each guided by what the passes before it
// learned and recorded into the guiding field; then the image, with the settings' samples, guided by all of
// them and recording nothing. The image is the last render's alone, as in Practical Path Guiding (the
// training images thrown away, the estimate unbiased whatever the guide learned), or every pass's image
// weighted by the inverse of its measured variance, as Müller's 2019 notes do (the training samples not
// wasted; the weights, measured from the same samples, bias it slightly). Every pass renders the whole image
// and records deterministically (fixed-point sums), so the image is the same for any number of threads; but a
// pass depends on all the passes before it, so a guided render cannot be split into pieces of its samples.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "01_ray_generation/camera.hpp"
#include "04_direct_lighting/render_scene.hpp"
#include "06_monte_carlo/path_tracer.hpp"
#include "guiding_field.hpp"
#include "rt/core/enum_names.hpp"
#include "rt/render/render_loop.hpp"

namespace rt {

// What the image is made of.
enum class PassCombination {
    kLast,             // the last render alone
    kInverseVariance,  // every pass's image, weighted by 1 / its variance
};

constexpr auto names_of(PassCombination) {
    return enum_names<PassCombination>("--combine-passes", {{PassCombination::kLast, "last"},
                                                            {PassCombination::kInverseVariance, "variance"}});
}

struct GuidedRenderOptions {
    int training_passes = 5;  // of 1, 2, …, 2^(passes − 1) spp (0: chapter 06's paths, unguided)
    PassCombination combination = PassCombination::kInverseVariance;  // measured better: lesson § 7
    GuidingSettings field;
};

// What a training pass did.
struct TrainingPass {
    int samples_per_pixel = 0;
    double seconds = 0;
    RayCounts rays;
    std::size_t leaves = 0;  // the spatial tree's, after the pass
    std::size_t bytes = 0;   // the trees', after the pass
    double variance = 0;     // its image's, measured under kInverseVariance (0: not measured)
};

struct GuidedRender {
    RenderResult result;  // the image; its time and rays include the training passes'
    std::vector<TrainingPass> passes;
    std::size_t bytes = 0;  // the trees' memory at the end
};

// What to do with the field once trained, before the image (the lesson's picture of it), with the tracer.
using TrainedField = std::function<void(const GuidingField&, const PathTracer&)>;

// Renders `prepared` with chapter 06's paths (their options `options`) guided as the header says.
GuidedRender render_guided(const RenderScene& prepared, const PinholeCamera& camera,
                           const RenderSettings& settings, const PathOptions& options,
                           const GuidedRenderOptions& guided, const TrainedField& trained = nullptr);

// The same on `scene` as the chapter's run renders it: what `simulated` holds, on chapter 07's materials (its
// dielectrics), with a camera of the settings' size.
GuidedRender render_guided(const Scene& scene, const EffectSet& simulated, const RenderSettings& settings,
                           PathOptions options, const GuidedRenderOptions& guided,
                           const TrainedField& trained = nullptr);

// The summary's lines: the passes, their rays, the trees' memory.
std::vector<std::string> guiding_notes(const GuidedRender& render, const GuidedRenderOptions& guided);

// The images weighted by the inverse of their variances (the mean over the pixels of the variance of each
// pixel's luminance): Σ I_k / v_k / Σ 1 / v_k. An image of variance 0 (one sample per pixel: not measured) is
// left out; if all are, the last image.
Image combined_by_variance(const std::vector<Image>& images, const std::vector<double>& variances);

// The seed of training pass k: another stream of numbers than the image's and every other pass's.
std::uint64_t training_seed(std::uint64_t seed, int pass);

}  // namespace rt
