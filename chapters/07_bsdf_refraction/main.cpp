// Chapter 07: BSDF refraction. The path tracer of chapter 06 with the smooth dielectric: Snell's law, the
// exact Fresnel reflectance, total internal reflection, Beer–Lambert absorption. `--fresnel-study` measures
// Schlick's approximation against the exact form (error and time); `--depth-study` measures the depth glass
// needs (RMSE against a converged reference and time for each maximum depth); `--max-depth` renders with one.
#include <cstdio>
#include <string>
#include <vector>

#include "bsdf_render.hpp"
#include "depth_study.hpp"
#include "fresnel_study.hpp"
#include "refraction_materials.hpp"
#include "rt/app.hpp"
#include "rt/effects.hpp"
#include "rt/image_io.hpp"

namespace {

using namespace rt;

void print_fresnel_study(Real ior, const std::string& csv) {
    const int angles = 100001;
    const auto rows = fresnel_study(ior, angles, 15);
    std::printf(
        "Schlick against the exact Fresnel reflectance, %d angles in [0, 90] degrees; time: median of 15 "
        "sweeps\n",
        angles);
    std::printf("%-8s %-10s %12s %12s %14s %12s %12s\n", "eta", "side", "max error", "mean error",
                "at theta (deg)", "exact ns", "schlick ns");
    for (const FresnelStudyRow& r : rows) {
        std::printf("%-8.4f %-10s %12.4e %12.4e %14.3f %12.2f %12.2f\n", double(r.eta),
                    r.eta >= 1 ? "entering" : "leaving", r.max_error, r.mean_error, r.max_error_angle,
                    r.exact_ns, r.schlick_ns);
    }
    if (!csv.empty()) {
        write_fresnel_csv(ior, 91, csv);
        std::printf("wrote %s\n", csv.c_str());
    }
}

// The index of the scene's first dielectric (1.5 without one).
Real scene_ior(const Scene& scene) {
    for (const Material& m : scene.materials)
        if (effect_of(m) == Effect::kRefraction) return m.ior;
    return Real(1.5);
}

std::vector<std::string> notes_for(const Scene& scene, Renderer renderer, const EffectSet& simulated) {
    std::vector<std::string> notes{"renderer: " + std::string(to_string(renderer))};
    const MaterialTable materials(scene, simulated, refraction_materials());
    for (const std::string& note : materials.notes()) notes.push_back(note);
    return notes;
}

}  // namespace

int main(int argc, char** argv) {
    std::optional<int> max_depth;
    std::string sampling = "mis";
    std::string sampler = "stratified";
    bool fresnel = false;
    std::string csv;
    bool depth = false;
    std::vector<int> depths{1, 2, 4, 8, 16};
    int reference_spp = 4096;
    std::string cache = ".";
    const ChapterInfo chapter{
        "ch07_bsdf_refraction",
        "Chapter 07: BSDF refraction: Snell, Fresnel (exact and Schlick), total internal "
        "reflection, Beer-Lambert, the sampled smooth dielectric in the path tracer",
        "ch07_default.json", kRefractionChapterEffects};
    auto flags = [&](CLI::App& app) {
        app.add_option("--max-depth", max_depth,
                       "End every path after this many bounces (chapter 05's depth rule) instead of Russian "
                       "roulette")
            ->check(CLI::Range(1, 1000));
        app.add_option("--sampling", sampling,
                       "How chapter 06's loop draws directions: uniform|cosine|brdf|light|mis")
            ->check(CLI::IsMember({"uniform", "cosine", "brdf", "light", "mis"}));
        app.add_option(
               "--sampler", sampler,
               "Where a sample's numbers come from: independent|stratified|sobol (Owen-scrambled Sobol)")
            ->check(CLI::IsMember({"independent", "stratified", "sobol"}));
        CLI::Option* fresnel_flag = app.add_flag("--fresnel-study", fresnel,
                     "Schlick against the exact Fresnel reflectance: max and mean error, ns per evaluation");
        CLI::Option* depth_flag = app.add_flag(
            "--depth-study", depth, "RMSE against a converged reference and time for each --depths (fixed maximum depth)");
        app.add_option("--csv", csv,
                       "With --fresnel-study: write R(theta) both ways to this CSV file; with --depth-study: "
                       "its table")->check(only_with({{fresnel_flag}, {depth_flag}}));
        app.add_option("--depths", depths, "With --depth-study: the maximum depths")
            ->check(CLI::Range(1, 1000))->check(only_with({{depth_flag}}));
        app.add_option("--reference-spp", reference_spp, "With --depth-study: spp of the reference")
            ->check(CLI::Range(1, 1 << 20))->check(only_with({{depth_flag}}));
        app.add_option("--cache", cache, "With --depth-study: folder of the cached reference PFM")->check(only_with({{depth_flag}}));
    };
    auto render = [&](const RunContext& context) -> std::optional<ChapterRun> {
        const Scene& scene = context.scene;
        if (fresnel) {
            print_fresnel_study(scene_ior(scene), csv);
            return std::nullopt;
        }
        PathOptions options;
        options.simulated = context.simulated;
        options.strategy = sampling_strategy_from_string(sampling);
        options.sampler = point_set_from_string(sampler);
        if (max_depth) options.termination = {Termination::kMaxDepth, *max_depth};
        if (depth) {
            if (!csv.empty()) check_writable("--csv", csv);
            bool cached = false;
            std::printf("reference: %d spp, Russian roulette, %dx%d ...\n", reference_spp,
                        context.settings.width, context.settings.height);
            std::fflush(stdout);
            const Image reference =
                glass_depth_reference(scene, context.settings, options, reference_spp, cache, cached);
            std::printf("  %s\n", cached ? "read from the cache" : "rendered and cached");
            const auto rows = glass_depth_study(scene, context.settings, options, reference, depths);
            std::printf("%9s %5s %12s %12s %12s %10s %12s\n", "max depth", "spp", "RMSE", "rel. MSE",
                        "mean error", "time (s)", "rays");
            for (const GlassDepthRow& r : rows) {
                std::printf("%9d %5d %12.4e %12.4e %+12.4e %10.3f %12llu\n", r.max_depth,
                            context.settings.samples_per_pixel, r.rmse, r.relative_mse, r.mean_error,
                            r.seconds, static_cast<unsigned long long>(r.rays));
            }
            if (!csv.empty()) write_glass_depth_csv(rows, context.settings.samples_per_pixel, csv);
            return std::nullopt;
        }
        const Renderer renderer = choose_renderer(context.simulated);
        ChapterRun run{render_with(renderer, scene, context.simulated, context.settings, options),
                       notes_for(scene, renderer, context.simulated), std::nullopt};
        run.notes.push_back("sampling: " + sampling + ", sampler: " + sampler +
                            (max_depth ? ", termination: max depth " + std::to_string(*max_depth)
                                       : std::string(", termination: Russian roulette")));
        return run;
    };
    return run_chapter(argc, argv, chapter, flags, render);
}
