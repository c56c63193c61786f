// Chapter 07: BSDF refraction. The path tracer of chapter 06 with the smooth dielectric: Snell's law, the
// exact Fresnel reflectance, total internal reflection, Beer–Lambert absorption. `--fresnel-study` measures
// Schlick's approximation against the exact form (error and time); `--depth-study` measures the depth glass
// needs (RMSE against a converged reference and time for each maximum depth); `--termination depth
// --max-depth N` renders with one.
#include "05_recursive_gi/termination_flags.hpp"
#include "06_monte_carlo/sampling_flags.hpp"
#include "bsdf_render.hpp"
#include "depth_study.hpp"
#include "fresnel_study.hpp"
#include "refraction_notes.hpp"
#include "rt/flags/study_flags.hpp"
#include "rt/run/app.hpp"

int main(int argc, char** argv) {
    using namespace rt;
    PathOptions options;
    TerminationFlags termination{options.termination, std::nullopt};  // chapter 06's rule until --termination
    bool fresnel = false;
    bool depth = false;
    GlassDepthRequest depth_request;
    const ChapterInfo chapter{
        "ch07_bsdf_refraction",
        "Chapter 07: BSDF refraction: Snell, Fresnel (exact and Schlick), total internal "
        "reflection, Beer-Lambert, the sampled smooth dielectric in the path tracer",
        "ch07_default.json", kRefractionChapterEffects};
    auto flags = [&](CLI::App& app) {
        add_termination_flags(app, termination);
        add_sampling_flag(app, options.strategy, options.quad_lights);
        add_sampler_flag(app, options.sampler);
        CLI::Option* fresnel_flag = app.add_flag(
            "--fresnel-study", fresnel,
            "Schlick against the exact Fresnel reflectance: max and mean error, ns per evaluation");
        CLI::Option* depth_flag = app.add_flag(
            "--depth-study", depth,
            "RMSE against a converged reference and time for each --depths (fixed maximum depth)");
        add_study_option(app, kCsvOption, depth_request.csv, {{fresnel_flag}, {depth_flag}},
                         "With --fresnel-study: write R(theta) both ways to this CSV file; with --depth-study: "
                         "its table");
        app.add_option("--depths", depth_request.depths, "With --depth-study: the maximum depths")
            ->check(CLI::Range(1, 1000))
            ->check(only_with({{depth_flag}}));
        add_reference_spp_option(app, depth_request.reference_spp, 1, {{depth_flag}});
        add_study_option(app, kCacheOption, depth_request.cache, {{depth_flag}});
    };
    auto render = [&](const RunContext& context) -> std::optional<ChapterRun> {
        const Scene& scene = context.scene;
        if (fresnel) {
            run_fresnel_study(scene, depth_request.csv);
            return std::nullopt;
        }
        options.simulated = context.simulated;
        options.termination = termination.resolved(scene);
        if (depth) {
            run_glass_depth_study(scene, context.settings, options, depth_request);
            return std::nullopt;
        }
        const Renderer renderer = choose_renderer(context.simulated);
        return ChapterRun{render_with(renderer, scene, context.simulated, context.settings, options),
                          refraction_notes(scene, renderer, options), std::nullopt};
    };
    return run_chapter(argc, argv, chapter, flags, render);
}
