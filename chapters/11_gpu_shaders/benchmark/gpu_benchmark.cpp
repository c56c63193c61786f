// What the shaders cost against the CPU, measured (not a test): `ch11_benchmark` prints the tables of the
// lesson. On the glass Cornell box (cornell.json) and on the same box with its glass made diffuse white (no
// refraction: paths that stay alike from one pixel to the next), --rounds rounds of, alternately, chapter
// 07's C++ renderer on --threads threads, the compute shader and the fragment shader, each one render of
// --width × --height × --spp; it prints each one's median samples per second and the medians' ratios.
// The renders alternate, so each sees the same load. The same program runs unchanged on a machine with a
// GPU: EGL then offers its driver (--egl device, if Mesa's llvmpipe answers the surfaceless platform first);
// the first line says which OpenGL it measured.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "07_bsdf_refraction/bsdf_render.hpp"
#include "gl_context.hpp"
#include "gpu_render.hpp"
#include "rt/core/median.hpp"
#include "rt/flags/enum_flag.hpp"
#include "rt/io/assets.hpp"
#include "rt/io/effects.hpp"
#include "rt/io/scene_loader.hpp"
#include "rt/run/strict_flags.hpp"

namespace {

using namespace rt;

double samples_per_second(const RenderResult& r) {
    return double(r.samples) / std::max(r.seconds, 1e-9);
}

struct Rates {
    std::vector<double> cpu, compute, fragment;
};

// `simulated` without refraction renders the scene without glass: the material table shades each dielectric
// as its stand-in, a light grey Lambert surface (albedo 0.73).
Rates measure(const GlContext& gl, const Scene& scene, const EffectSet& simulated, const RenderSettings& settings,
              int rounds) {
    const GpuRenderer compute(gl, scene, simulated, ShaderKind::kCompute);
    const GpuRenderer fragment(gl, scene, simulated, ShaderKind::kFragment);
    // One round unmeasured: the driver's compile, the caches.
    compute.render(settings);
    fragment.render(settings);
    // The CPU traces the shader's paths: its stratified Pcg32 numbers.
    PathOptions stratified;
    stratified.sampler = PointSet::kStratified;
    Rates rates;
    for (int round = 0; round < rounds; ++round) {
        rates.cpu.push_back(
            samples_per_second(render_with(Renderer::kPaths, scene, simulated, settings, stratified)));
        rates.compute.push_back(samples_per_second(compute.render(settings)));
        rates.fragment.push_back(samples_per_second(fragment.render(settings)));
    }
    return rates;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Chapter 11's benchmark: samples per second of the shaders against the C++ renderer"};
    std::string scene_file = scene_path("cornell.json").string();
    int width = 128, height = 128, spp = 16, rounds = 5, threads = 2;
    std::string egl = "auto";
    app.add_option("--scene", scene_file, "The scene (its glass is also made diffuse for the second table)");
    app.add_option("--width", width)->check(CLI::Range(8, 8192));
    app.add_option("--height", height)->check(CLI::Range(8, 8192));
    app.add_option("--spp", spp)->check(CLI::Range(1, 1 << 16));
    app.add_option("--rounds", rounds, "Rounds of the three renders, alternately")->check(CLI::Range(1, 100));
    app.add_option("--threads", threads, "The C++ renderer's threads")->check(CLI::Range(1, 1024));
    app.add_option("--egl", egl, "EGL platform: auto|surfaceless|device")
        ->check(choices<EglPlatform>());
    if (const auto stop = rt::read_flags(app, argc, argv)) return *stop;
    try {
        const GlContext gl(from_string<EglPlatform>(egl));
        const char* lp_threads = std::getenv("LP_NUM_THREADS");
        std::printf("OpenGL: %s%s%s\n", gl.description().c_str(), gl.software() ? "; LP_NUM_THREADS=" : "",
                    gl.software() ? (lp_threads ? lp_threads : "unset (one thread per core)") : "");
        std::printf(
            "CPU: chapter 07's path renderer on %d threads; %dx%d, %d spp, median of %d rounds, "
            "alternately\n\n",
            threads, width, height, spp, rounds);
        RenderSettings settings;
        settings.width = width;
        settings.height = height;
        settings.samples_per_pixel = spp;
        settings.seed = 1;
        settings.threads = threads;
        settings.progress = ProgressStyle::kNone;
        const Scene scene = load_scene(scene_file);
        std::printf("%-28s %14s %14s %14s %12s %12s\n", "scene", "CPU samples/s", "compute", "fragment",
                    "compute/CPU", "fragment/CPU");
        for (const bool glass : {true, false}) {
            const EffectSet simulated =
                glass ? needed(scene) : needed(scene).without({Effect::kRefraction});
            const Rates r = measure(gl, scene, simulated, settings, rounds);
            const double cpu = median(r.cpu), compute = median(r.compute), fragment = median(r.fragment);
            std::printf("%-28s %14.4g %14.4g %14.4g %12.3f %12.3f\n",
                        glass ? "as given (glass)" : "glass made diffuse", cpu, compute, fragment,
                        compute / cpu, fragment / cpu);
        }
        // Divergence: the compute shader with each pixel's own random numbers, and with every pixel taking
        // pixel 0's (neighbouring paths alike), alternately.
        const EffectSet simulated = needed(scene);
        const GpuRenderer compute(gl, scene, simulated, ShaderKind::kCompute);
        compute.render(settings);
        std::vector<double> own, shared;
        for (int round = 0; round < rounds; ++round) {
            compute.share_random_streams(false);
            own.push_back(samples_per_second(compute.render(settings)));
            compute.share_random_streams(true);
            shared.push_back(samples_per_second(compute.render(settings)));
        }
        std::printf(
            "\ncompute shader, divergence: %.4g samples/s with each pixel's own random numbers, %.4g "
            "with pixel 0's in every pixel (paths alike): %.3fx\n",
            median(own), median(shared), median(shared) / median(own));
    } catch (const GlUnavailable& e) {
        std::fprintf(stderr, "ch11_benchmark: %s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "ch11_benchmark: %s\n", e.what());
        return 1;
    }
    return 0;
}
