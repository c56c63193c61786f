#include "guided_render.hpp"

#include <algorithm>
#include <array>
#include <cstdio>

#include "06_monte_carlo/render_paths.hpp"
#include "07_bsdf_refraction/refraction_materials.hpp"
#include "guided_tracer.hpp"

namespace rt {

namespace {

std::string megabytes(std::size_t bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g MB", double(bytes) / 1e6);
    return text;
}

std::string ray_counts(const RayCounts& rays) {
    std::string text;
    for (int k = 0; k < kRayKindCount; ++k) {
        text += (k > 0 ? ", " : "") + std::string(kRayKindNames[std::size_t(k)]) + " " +
                std::to_string(rays.count[std::size_t(k)]);
    }
    return text;
}

// The scene's box: its BVH's root, or the camera's surroundings where only planes fill it.
Aabb scene_box(const World& world, const Vec3& eye) {
    const auto& nodes = world.bvh().nodes();
    if (!nodes.empty()) return nodes.front().box();
    return {eye - Vec3(1), eye + Vec3(1)};
}

// A render of `tracer`'s paths, and, under kInverseVariance, its image's variance (the squares of the samples
// summed beside it).
struct MeasuredRender {
    RenderResult result;
    double variance = 0;
};

MeasuredRender render_measured(const GuidedTracer& tracer, const PinholeCamera& camera,
                               const RenderSettings& settings, PassCombination combination) {
    if (combination == PassCombination::kLast) return {render_paths(tracer, camera, settings)};
    std::array<PixelSums, 1> squares;
    MeasuredRender out;
    out.result = render_layers(settings, squares, [&](const PixelSample& s, Pcg32& rng, RayCounts& rays) {
        const Color c = sample_radiance(tracer, camera, settings, s, rng, rays);
        return std::array<Color, 2>{c, c * c};
    });
    const Image variance = variance_image(out.result.sums, squares[0]);
    double sum = 0;
    for (const Color& v : variance.pixels()) sum += double(luminance(v));
    out.variance = sum / double(std::max<std::size_t>(variance.pixel_count(), 1));
    return out;
}

}  // namespace

Image combined_by_variance(const std::vector<Image>& images, const std::vector<double>& variances) {
    Image out(images.back().width(), images.back().height());
    double weights = 0;
    for (std::size_t k = 0; k < images.size(); ++k) {
        if (!(variances[k] > 0)) continue;
        const double w = 1 / variances[k];
        weights += w;
        for (std::size_t i = 0; i < out.pixel_count(); ++i)
            out.pixels()[i] += Real(w) * images[k].pixels()[i];
    }
    if (!(weights > 0)) return images.back();
    for (Color& c : out.pixels()) c /= Real(weights);
    return out;
}

std::uint64_t training_seed(std::uint64_t seed, int pass) {
    return seed + 0x9E3779B97F4A7C15ull * std::uint64_t(pass + 1);
}

GuidedRender render_guided(const RenderScene& prepared, const PinholeCamera& camera,
                           const RenderSettings& settings, const PathOptions& options,
                           const GuidedRenderOptions& guided, const TrainedField& trained) {
    const PathTracer tracer(prepared.world, prepared.materials, prepared.lights, options);
    GuidingField field(guiding_bounds(scene_box(prepared.world, camera.eye), camera.eye), guided.field);
    GuidedRender out;
    double training_seconds = 0;
    RayCounts training_rays;
    std::vector<Image> images;
    std::vector<double> variances;
    for (int k = 0; k < guided.training_passes; ++k) {
        RenderSettings pass = settings;
        pass.samples_per_pixel = 1 << k;
        pass.seed = training_seed(settings.seed, k);
        pass.progress = ProgressStyle::kNone;
        pass.observer = nullptr;
        MeasuredRender m =
            render_measured(GuidedTracer(tracer, field, true), camera, pass, guided.combination);
        const RenderResult& r = m.result;
        field.finish_pass();
        out.passes.push_back(
            {pass.samples_per_pixel, r.seconds, r.rays, field.leaf_count(), field.bytes(), m.variance});
        training_seconds += r.seconds;
        training_rays += r.rays;
        images.push_back(std::move(m.result.image));
        variances.push_back(m.variance);
    }
    if (trained) trained(field, tracer);
    // Without training passes there is nothing to weigh: the image is chapter 06's, which splits and resumes.
    const PassCombination rule = images.empty() ? PassCombination::kLast : guided.combination;
    MeasuredRender last = render_measured(GuidedTracer(tracer, field, false), camera, settings, rule);
    out.result = std::move(last.result);
    if (guided.combination == PassCombination::kInverseVariance && !images.empty()) {
        images.push_back(out.result.image);
        variances.push_back(last.variance);
        out.result.image = combined_by_variance(images, variances);
    }
    out.result.seconds += training_seconds;
    out.result.rays += training_rays;
    out.bytes = field.bytes();
    return out;
}

GuidedRender render_guided(const Scene& scene, const EffectSet& simulated, const RenderSettings& settings,
                           PathOptions options, const GuidedRenderOptions& guided,
                           const TrainedField& trained) {
    options.simulated = simulated;
    const RenderScene prepared(scene, simulated, refraction_materials());
    const PinholeCamera camera = make_pinhole_camera(scene.camera, settings.width, settings.height);
    return render_guided(prepared, camera, settings, options, guided, trained);
}

std::vector<std::string> guiding_notes(const GuidedRender& render, const GuidedRenderOptions& guided) {
    std::vector<std::string> notes;
    const GuidingSettings& f = guided.field;
    if (render.passes.empty()) {
        notes.push_back("guiding: no training pass: chapter 06's paths, unguided");
        return notes;
    }
    char text[400];
    std::snprintf(
        text, sizeof text,
        "guiding: %zu training passes, then the image; one-sample MIS, guide chosen with alpha %.2f; "
        "spatial split past %.0f sqrt(2^k) vertices, quadrants split past %.3g of the energy, depth "
        "<= %d; image: %s",
        render.passes.size(), double(f.guided_fraction), f.spatial_threshold, f.energy_threshold, f.max_depth,
        guided.combination == PassCombination::kLast ? "the last render" : "passes weighted by 1 / variance");
    notes.push_back(text);
    for (std::size_t k = 0; k < render.passes.size(); ++k) {
        const TrainingPass& p = render.passes[k];
        std::snprintf(text, sizeof text,
                      "training pass %zu: %d spp, %.3f s, %zu leaves, trees %s, variance %.3g; rays: ", k + 1,
                      p.samples_per_pixel, p.seconds, p.leaves, megabytes(p.bytes).c_str(), p.variance);
        notes.push_back(text + ray_counts(p.rays));
    }
    notes.push_back("guiding trees' memory: " + megabytes(render.bytes) +
                    "; the time and rays below include the training passes");
    return notes;
}

}  // namespace rt
