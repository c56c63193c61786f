// Time to a relative MSE of 10⁻³ for each --distance-sampling, with quad lights by area and (free flight
// and MIS, what --tracer auto picks) by solid angle, on a scene of fog: a converged reference (the mean of
// two MIS renders A and B, its own noise mean((A − B)²) / 4 subtracted, as chapter 06's --converge does),
// then the five strategies rendered alternately, `runs` times each at `spp` on one thread. An unbiased
// estimator's relative MSE falls as 1 / time, so time to 10⁻³ = seconds × relative MSE / 10⁻³; the table
// gives each strategy's median. Not a test: `ch09_distance_benchmark [scene] [size] [spp] [reference spp]
// [runs] [density] [black]` (`--help` gives the defaults).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <string>
#include <vector>

#include "rt/core/error_metrics.hpp"
#include "rt/core/median.hpp"
#include "rt/io/assets.hpp"
#include "rt/io/effects.hpp"
#include "rt/io/scene_loader.hpp"
#include "rt/run/strict_flags.hpp"
#include "volume_path_tracer.hpp"

namespace {

using namespace rt;

// The positional arguments, in order, with their defaults.
struct Arguments {
    std::string file = "ch09_thin_fog.json";
    int size = 64, spp = 16, reference_spp = 4096, runs = 5;
    double density = 1;
    std::string surfaces = "as given";
};

void add_arguments(CLI::App& app, Arguments& a) {
    app.option_defaults()->always_capture_default();
    app.add_option("scene", a.file, "A scene of assets/scenes");
    app.add_option("size", a.size, "Image width and height")->check(CLI::Range(1, 4096));
    app.add_option("spp", a.spp, "Samples per pixel of each run")->check(CLI::Range(1, 1 << 20));
    app.add_option("reference-spp", a.reference_spp, "Samples per pixel of the reference")
        ->check(CLI::Range(2, 1 << 24));
    app.add_option("runs", a.runs, "Alternating runs of each strategy")->check(CLI::Range(1, 99));
    app.add_option("density", a.density, "The fog's coefficients scaled by this")->check(CLI::PositiveNumber);
    app.add_option("surfaces", a.surfaces, "black: every surface that does not emit made black")
        ->check(CLI::IsMember({"as given", "black"}));
}

// The scene as measured: its fog's coefficients scaled by `density`, and with `black`, every surface that
// does not emit made black.
void adjust_scene(Scene& scene, double density, bool black) {
    if (scene.medium) {
        scene.medium->sigma_a *= Real(density);
        scene.medium->sigma_s *= Real(density);
    }
    if (black)
        for (Material& m : scene.materials)
            if (m.emission == Color(0)) m.albedo = Color(0);
}

}  // namespace

int main(int argc, char** argv) {
    Arguments arguments;
    CLI::App app("ch09_distance_benchmark: time to a relative MSE of 1e-3 for each distance sampling");
    add_arguments(app, arguments);
    if (const auto stop = read_flags(app, argc, argv)) return *stop;
    const auto& [file, size, spp, reference_spp, runs, density, surfaces] = arguments;
    Scene scene;
    try {
        scene = load_scene(scene_path(file.c_str()));
    } catch (const InputError& e) {
        std::fprintf(stderr, "ch09_distance_benchmark: %s\n", e.what());
        return kExitBadInput;
    }
    const bool black = surfaces == "black";
    adjust_scene(scene, density, black);
    const EffectSet simulated = needed(scene) & EffectSet::all();
    const Renderer renderer = choose_renderer(simulated);
    RenderSettings settings;
    settings.width = settings.height = size;
    settings.progress = ProgressStyle::kNone;
    struct Strategy {
        DistanceSampling distance;
        QuadLightSampling quad_lights;
    };
    const auto render = [&](Strategy strategy, int samples, std::uint64_t seed, int threads) {
        MediumWalk walk;
        walk.distance = strategy.distance;
        PathOptions options;
        options.quad_lights = strategy.quad_lights;
        RenderSettings s = settings;
        s.samples_per_pixel = samples;
        s.seed = seed;
        s.threads = threads;
        return render_with_media(renderer, scene, simulated, s, options, walk);
    };
    const Strategy reference_strategy{DistanceSampling::kMis, QuadLightSampling::kArea};
    const RenderResult a = render(reference_strategy, reference_spp / 2, 1001, 2);
    const RenderResult b = render(reference_strategy, reference_spp / 2, 1002, 2);
    Image reference = a.image;
    for (std::size_t i = 0; i < reference.pixels().size(); ++i)
        reference.pixels()[i] = (a.image.pixels()[i] + b.image.pixels()[i]) * Real(0.5);
    const double reference_noise = compare(a.image, reference).relative_mse;  // mean((A − B)²) / 4, relative
    const std::vector<Strategy> strategies = {{DistanceSampling::kFreeFlight, QuadLightSampling::kArea},
                                              {DistanceSampling::kEquiangular, QuadLightSampling::kArea},
                                              {DistanceSampling::kMis, QuadLightSampling::kArea},
                                              {DistanceSampling::kFreeFlight, QuadLightSampling::kSolidAngle},
                                              {DistanceSampling::kMis, QuadLightSampling::kSolidAngle}};
    std::vector<std::vector<double>> times(strategies.size()), errors(strategies.size()),
        seconds(strategies.size()), shadow(strategies.size());
    for (int run = 0; run < runs; ++run)
        for (std::size_t k = 0; k < strategies.size(); ++k) {
            const RenderResult r = render(strategies[k], spp, std::uint64_t(run + 1), 1);
            const double relative_mse = compare(r.image, reference).relative_mse - reference_noise;
            errors[k].push_back(relative_mse);
            seconds[k].push_back(r.seconds);
            shadow[k].push_back(double(r.rays[RayKind::kShadow]) / double(r.samples));
            times[k].push_back(r.seconds * relative_mse / 1e-3);
        }
    std::printf(
        "%s (fog density x%g%s), %dx%d, %d spp per run, 1 thread, %d alternating runs; reference %d spp "
        "(MIS), its own relative MSE %.2e\n",
        file.c_str(), density, black ? ", black surfaces" : "", size, size, spp, runs, reference_spp,
        reference_noise);
    std::printf(
        "| distance sampling, quad lights | relative MSE | seconds | shadow rays / sample | time to 1e-3 | "
        "vs free flight, area |\n");
    std::printf("|---|---|---|---|---|---|\n");
    for (std::size_t k = 0; k < strategies.size(); ++k)
        std::printf("| %s, %s | %.2e | %.3f | %.2f | %.2f s | %.2f× |\n",
                    std::string(to_string(strategies[k].distance)).c_str(),
                    std::string(to_string(strategies[k].quad_lights)).c_str(), median(errors[k]),
                    median(seconds[k]), median(shadow[k]), median(times[k]),
                    median(times[k]) / median(times[0]));
    return 0;
}
