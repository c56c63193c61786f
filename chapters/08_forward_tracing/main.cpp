// Chapter 08: forward (light) tracing. Paths start at the lights and reach the camera through a lens
// aperture (`--variant aperture --aperture R`) or by connecting every vertex to the pinhole (`--variant
// connect`, the default); `--tracer reverse` renders the same scene with chapter 07's renderer beside it.
// `--tracer combined` adds the two: chapter 06's paths for everything but the caustics the camera sees, light
// paths for those (combined_render.hpp). `--forward-study` measures what reverse tracing saves (see
// forward_study.hpp).
#include <algorithm>
#include <cstdio>
#include <string>

#include "01_ray_generation/camera.hpp"
#include "02_intersection/world.hpp"
#include "04_direct_lighting/render_scene.hpp"
#include "07_bsdf_refraction/bsdf_render.hpp"
#include "07_bsdf_refraction/refraction_materials.hpp"
#include "combined_render.hpp"
#include "forward_study.hpp"
#include "light_tracer.hpp"
#include "rt/app.hpp"
#include "rt/errors.hpp"

namespace {

using namespace rt;

std::vector<std::string> scene_notes(const Scene& scene, const MaterialTable& materials,
                                     const LightSet& lights, bool forward) {
    std::vector<std::string> notes = materials.notes();
    const std::vector<bool> used = scene.used_materials();
    for (std::size_t i = 0; i < materials.size() && forward; ++i) {
        const Bsdf& bsdf = materials.bsdf(int(i));
        if (used[i] && is_delta(bsdf) && !is_black(bsdf)) {
            notes.push_back("material '" + scene.materials[i].name +
                            "': a delta BSDF (mirror or smooth glass): a pinhole cannot be connected to its "
                            "vertices, so the light tracer shows it black (what it reflects or refracts is "
                            "lost); the caustics it casts are found");
        }
    }
    if (forward && lights.environment) {
        notes.push_back("the environment light is not traced forward (no light paths start from it): black");
    }
    if (forward && !lights.points.empty()) {
        notes.push_back("point lights light the scene but are not seen themselves (as in every chapter)");
    }
    for (const std::string& u : lights.unsampled) notes.push_back("emitter not sampled as a light: " + u);
    return notes;
}

}  // namespace

int main(int argc, char** argv) {
    std::string tracer_name = "forward";
    std::string variant = "connect";
    Real aperture = 1;
    bool caustics_only = false;
    Real light_paths = CombinedOptions{}.light_paths_per_sample;
    int caustic_bounces = CombinedOptions{}.caustic_bounces;
    std::string sampler = "stratified";
    StudyOptions study;
    bool run_study = false;
    const ChapterInfo chapter{
        "ch08_forward_tracing",
        "Chapter 08: forward (light) tracing: paths from the lights, through an aperture or connected to the "
        "camera",
        "ch08_default.json",
        kRefractionChapterEffects,
        {},
        [&]() -> std::string {
            if (tracer_name == "forward")
                return "forward tracing splats each light path into whichever pixels it reaches, so the image has "
                       "no samples per pixel to split: it renders whole; --tracer reverse can be split";
            return tracer_name == "combined" ? "the combined tracer adds light paths splatted into any pixel: it "
                                               "renders whole; --tracer reverse can be split"
                                             : "";
        }};
    auto flags = [&](CLI::App& app) {
        CLI::Option* tracer_flag = app.add_option("--tracer", tracer_name,
                       "forward (light paths), reverse (chapter 07's renderer for the effects simulated) or "
                       "combined (chapter 06's paths, and light paths for the caustics the camera sees)")
            ->check(CLI::IsMember({"forward", "reverse", "combined"}));
        const CLI::Validator combined = only_with({{tracer_flag, {"combined"}}});
        app.add_option("--light-paths", light_paths,
                       "With --tracer combined: light paths for the caustics per camera sample")
            ->check(CLI::Range(0.0, 1024.0))->check(combined);
        app.add_option("--caustic-bounces", caustic_bounces,
                       "With --tracer combined: light paths carry the paths that meet glass or a mirror "
                       "after at most this many diffuse bounces from the camera (E D{1..K} S ...)")
            ->check(CLI::Range(1, kSafetyDepthCap))->check(combined);
        app.add_option("--sampler", sampler,
                       "With --tracer combined: where a camera sample's numbers come from: "
                       "independent|stratified|sobol")
            ->check(CLI::IsMember({"independent", "stratified", "sobol"}))->check(combined);
        CLI::Option* variant_flag = app.add_option("--variant", variant,
                       "How forward paths reach the camera: connect (every vertex to the pinhole) or "
                       "aperture (through a lens of radius --aperture)")
            ->check(CLI::IsMember({"connect", "aperture"}));
        app.add_option("--aperture", aperture, "With --variant aperture: the lens radius, scene units")
            ->check(CLI::PositiveNumber)->check(only_with({{variant_flag, {"aperture"}}}));
        app.add_flag("--caustics-only", caustics_only,
                     "Forward: only light that arrived straight from a mirror or glass (paths L...S D E)")
            ->check(only_with({{variant_flag, {"connect"}}}));
        CLI::Option* study_flag = app.add_flag(
            "--forward-study", run_study,
            "Measure on chapter 06's Cornell box the fraction of light paths that contribute and the "
            "time to chapter 06's RMSE; and where forward tracing wins and loses (ch08_default.json, "
            "ch08_mirror.json)");
        app.add_option("--study-size", study.size, "With --forward-study: image side in pixels")
            ->check(CLI::Range(8, 1024))->check(only_with({{study_flag}}));
        app.add_option("--study-paths", study.fraction_paths,
                       "With --forward-study: light paths per fraction")
            ->check(CLI::Range(1000, 1 << 30))->check(only_with({{study_flag}}));
        app.add_option("--reference-spp", study.reference_spp,
                       "With --forward-study: spp of chapter 06's converged reference")
            ->check(CLI::Range(2, 1 << 20))->check(only_with({{study_flag}}));
        app.add_option("--glass-reference-spp", study.glass_reference_spp,
                       "With --forward-study: spp of the mirror and glass scenes' references")
            ->check(CLI::Range(2, 1 << 20))->check(only_with({{study_flag}}));
        app.add_option("--cache", study.cache,
                       "With --forward-study: folder of the converged references (chapter 06's cache files)")
            ->check(only_with({{study_flag}}));
        app.add_option("--csv", study.csv, "With --forward-study: also write the time-to-RMSE table as CSV")
            ->check(only_with({{study_flag}}));
    };
    auto render = [&](const RunContext& context) -> std::optional<ChapterRun> {
        if (run_study) {
            study.threads = context.settings.threads;
            study.seed = context.settings.seed;
            run_forward_study(study);
            return std::nullopt;
        }
        const Scene& scene = context.scene;
        const RenderSettings& settings = context.settings;
        if (tracer_name == "combined") {
            CombinedOptions options;
            options.light_paths_per_sample = light_paths;
            options.caustic_bounces = caustic_bounces;
            options.paths.sampler = from_string<PointSet>(sampler);
            const CombinedResult r = render_combined(scene, context.simulated, settings, options);
            const MaterialTable materials(scene, context.simulated, refraction_materials());
            ChapterRun run{r.render, scene_notes(scene, materials, collect_lights(scene), false), std::nullopt};
            char line[320];
            if (r.split) {
                std::snprintf(line, sizeof line,
                              "tracer: combined; chapter 06's paths (sampler %s, %.3f s) for all paths but "
                              "E D{1..%d} S ... (the caustics the camera sees), %llu light paths for those "
                              "(%.3f s, %.4g%% reached the camera)",
                              sampler.c_str(), r.paths.seconds, caustic_bounces,
                              static_cast<unsigned long long>(r.caustics.render.samples),
                              r.caustics.render.seconds,
                              100.0 * double(r.caustics.contributing_paths) /
                                  double(std::max<std::uint64_t>(1, r.caustics.render.samples)));
            } else {
                std::snprintf(line, sizeof line,
                              "tracer: combined, by chapter 06's paths alone (sampler %s): light paths start "
                              "only at area and point lights and cross no medium, and this scene has other "
                              "light or a medium",
                              sampler.c_str());
            }
            run.notes.push_back(line);
            run.notes.push_back("rays: light paths' first rays counted as shadow, connections to the camera as "
                                "camera rays");
            return run;
        }
        const bool forward = tracer_name == "forward";
        // Light paths carry importance: the material table is built for it (chapter 07's glass scales
        // differently).
        const RenderScene prepared(scene, context.simulated, refraction_materials(),
                                   forward ? Transport::kImportance : Transport::kRadiance);
        ChapterRun run{{}, scene_notes(scene, prepared.materials, prepared.lights, forward), std::nullopt};
        if (!forward) {
            const Renderer renderer = choose_renderer(context.simulated);
            run.result = render_with(renderer, scene, context.simulated, settings);
            run.notes.push_back("tracer: reverse, chapter 07's renderer: " +
                                std::string(to_string(renderer)));
            return run;
        }
        const PinholeCamera camera = make_pinhole_camera(scene.camera, settings.width, settings.height);
        LightTracerOptions options;
        options.simulated = context.simulated;
        options.variant = camera_variant_from_string(variant);
        options.aperture_radius = aperture;
        options.paths = caustics_only ? LightPathSet::kCaustics : LightPathSet::kAll;
        const LightTracer tracer(prepared.world, prepared.materials, prepared.lights, camera, options);
        const std::uint64_t paths = paths_per_image(settings);
        const SplatResult r = render_light_tracing(tracer, settings, paths);
        run.result = r.render;
        char line[200];
        std::snprintf(
            line, sizeof line,
            "tracer: forward, variant %s; %llu light paths (spp x pixels), %.4g%% of them reached the "
            "camera",
            variant.c_str(), static_cast<unsigned long long>(r.render.samples),
            100.0 * double(r.contributing_paths) / double(std::max<std::uint64_t>(1, r.render.samples)));
        run.notes.push_back(line);
        run.notes.push_back(
            "rays: light-to-surface rays counted as shadow, connections to the camera as camera rays");
        return run;
    };
    return run_chapter(argc, argv, chapter, flags, render);
}
