// Chapter 08: forward (light) tracing. Paths start at the lights and reach the camera through a lens
// aperture (`--variant aperture --aperture R`) or by connecting every vertex to the pinhole (`--variant
// connect`, the default); `--tracer reverse` renders the same scene with chapter 06's path tracer beside it.
// `--forward-study` measures what reverse tracing saves (see forward_study.hpp).
#include <cstdio>
#include <string>

#include "camera.hpp"
#include "forward_study.hpp"
#include "light_tracer.hpp"
#include "path_tracer.hpp"
#include "rt/app.hpp"
#include "rt/errors.hpp"
#include "world.hpp"

namespace {

using namespace rt;

std::vector<std::string> scene_notes(const Scene& scene, const LightSet& lights, bool forward) {
    std::vector<std::string> notes;
    for (const Material& m : scene.materials) {
        if (m.type == MaterialType::kDielectric) {
            notes.push_back(
                "dielectric material '" + m.name +
                "': refraction is simulated from chapter 07 on; shaded as diffuse white (albedo 0.73)");
        }
        if (forward && m.type == MaterialType::kMirror) {
            notes.push_back(
                "mirror material '" + m.name +
                "': a pinhole cannot be connected to a mirror vertex, so the light tracer shows it "
                "black (what it reflects is lost); its caustics are found");
        }
    }
    if (forward && lights.environment) {
        notes.push_back("the environment light is not traced forward (no light paths start from it): black");
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
    StudyOptions study;
    bool run_study = false;
    const ChapterInfo chapter{
        "ch08_forward_tracing",
        "Chapter 08: forward (light) tracing: paths from the lights, through an aperture or connected to the "
        "camera",
        "ch08_default.json",
        EffectSet{Effect::kCameraRays, Effect::kShadows, Effect::kDirect, Effect::kReflection,
                  Effect::kGlossy, Effect::kIndirect}};
    auto flags = [&](CLI::App& app) {
        app.add_option("--tracer", tracer_name,
                       "forward (light paths) or reverse (chapter 06's path tracer, MIS)")
            ->check(CLI::IsMember({"forward", "reverse"}));
        app.add_option("--variant", variant,
                       "How forward paths reach the camera: connect (every vertex to the pinhole) or "
                       "aperture (through a lens of radius --aperture)")
            ->check(CLI::IsMember({"connect", "aperture"}));
        app.add_option("--aperture", aperture, "With --variant aperture: the lens radius, scene units")
            ->check(CLI::PositiveNumber);
        app.add_flag("--caustics-only", caustics_only,
                     "Forward: only light that arrived straight from a mirror (paths L...S D E)");
        app.add_flag("--forward-study", run_study,
                     "Measure on chapter 06's Cornell box: the fraction of light paths that contribute, time "
                     "to chapter 06's RMSE; and where forward tracing wins and loses (ch08_default.json)");
        app.add_option("--study-size", study.size, "With --forward-study: image side in pixels")
            ->check(CLI::Range(8, 1024));
        app.add_option("--study-paths", study.fraction_paths,
                       "With --forward-study: light paths for the fractions")
            ->check(CLI::Range(1000, 1 << 30));
        app.add_option("--cache", study.cache,
                       "With --forward-study: folder of the converged references (chapter 06's cache files)");
        app.add_option("--csv", study.csv, "With --forward-study: also write the time-to-RMSE table as CSV");
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
        const World world(scene);
        const LightSet lights = collect_lights(scene);
        const PinholeCamera camera = make_pinhole_camera(scene.camera, settings.width, settings.height);
        const bool forward = tracer_name == "forward";
        ChapterRun run{{}, scene_notes(scene, lights, forward), std::nullopt};
        if (!forward) {
            const PathTracer tracer(world, scene, lights, reverse_options(context.simulated));
            run.result = render_paths(tracer, camera, settings);
            run.notes.push_back("tracer: reverse (chapter 06, MIS)");
            return run;
        }
        LightTracerOptions options = forward_options(context.simulated);
        options.variant = camera_variant_from_string(variant);
        options.aperture_radius = aperture;
        options.caustics_only = caustics_only;
        const LightTracer tracer(world, scene, lights, camera, options);
        const std::uint64_t paths = std::uint64_t(settings.samples_per_pixel) *
                                    std::uint64_t(settings.width) * std::uint64_t(settings.height);
        const SplatResult r = render_light_tracing(tracer, settings, paths);
        run.result = r.render;
        char line[200];
        std::snprintf(
            line, sizeof line,
            "tracer: forward, variant %s; %llu light paths (spp x pixels), %.4g%% of them reached "
            "the camera",
            variant.c_str(), static_cast<unsigned long long>(r.render.samples),
            100.0 * double(r.contributing_paths) / double(std::max<std::uint64_t>(1, r.render.samples)));
        run.notes.push_back(line);
        run.notes.push_back(
            "rays: light-to-surface rays counted as shadow, connections to the camera as camera rays");
        return run;
    };
    return run_chapter(argc, argv, chapter, flags, render);
}
