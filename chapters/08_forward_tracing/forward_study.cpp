#include "forward_study.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "02_intersection/world.hpp"
#include "06_monte_carlo/convergence.hpp"
#include "07_bsdf_refraction/bsdf_render.hpp"
#include "07_bsdf_refraction/refraction_materials.hpp"
#include "rt/core/error_metrics.hpp"
#include "rt/core/errors.hpp"
#include "rt/io/assets.hpp"
#include "rt/io/image_io.hpp"
#include "rt/io/scene_loader.hpp"

namespace rt {
namespace {

RenderSettings study_settings(const StudyOptions& o, int spp) {
    RenderSettings s;
    s.width = o.size;
    s.height = o.size;
    s.samples_per_pixel = spp;
    s.seed = o.seed;
    s.threads = o.threads;
    s.progress = ProgressStyle::kNone;
    return s;
}

// Chapter 06's cached converged reference (convergence.hpp) of `s` at `spp`, said as `renderer`.
Reference reference_of(const StudyScene& s, const StudyOptions& o, int spp, const char* renderer) {
    std::printf("  converged reference (%s, %d spp) ...", renderer, spp);
    std::fflush(stdout);
    const Reference ref =
        converged_reference(s.prepared, PathOptions{}, s.camera, study_settings(o, 1), spp, o.cache);
    std::printf(" %s %s (its own RMSE about %.2e)\n", ref.cached ? "read" : "rendered and wrote",
                ref.file.string().c_str(), std::sqrt(ref.noise_mse));
    return ref;
}

void fractions(const StudyScene& s, const StudyOptions& o) {
    std::printf("\n1. Light paths that ever reach the camera (%s, %dx%d, %llu light paths each)\n",
                std::filesystem::path(s.scene.file).filename().c_str(), o.size, o.size,
                static_cast<unsigned long long>(o.fraction_paths));
    std::printf("%-28s %14s %12s %14s %10s\n", "variant", "contributing", "fraction", "camera rays/path",
                "time (s)");
    RenderSettings settings = study_settings(o, 1);
    auto row = [&](const char* name, LightTracerOptions options) {
        const LightTracer tracer(s.prepared.world, s.importance, s.prepared.lights, s.camera, options);
        const SplatResult r = render_light_tracing(tracer, settings, o.fraction_paths);
        std::printf("%-28s %14llu %12.4e %14.3f %10.3f\n", name,
                    static_cast<unsigned long long>(r.contributing_paths),
                    double(r.contributing_paths) / double(r.render.samples),
                    double(r.render.rays[RayKind::kCamera]) / double(r.render.samples), r.render.seconds);
    };
    for (Real radius : {Real(1), Real(4), Real(16), Real(64)}) {
        LightTracerOptions options;
        options.variant = CameraVariant::kAperture;
        options.aperture_radius = radius;
        char name[64];
        std::snprintf(name, sizeof name, "aperture, lens radius %g", double(radius));
        row(name, options);
    }
    row("connect (pinhole)", LightTracerOptions{});
    // Without the lamp's own point (which the camera sees whole): the paths whose bounces reach the camera.
    LightTracerOptions bounces_only;
    bounces_only.simulated = bounces_only.simulated.without({Effect::kCameraRays});
    row("connect, bounces only", bounces_only);
}

struct TimedRmse {
    int spp;
    double rmse;
    double seconds;
};

void time_to_same_rmse(const StudyScene& s, const StudyOptions& o) {
    std::printf("\n2. Time to the same RMSE as chapter 06's reverse path tracer (%s, %dx%d, %d threads)\n",
                std::filesystem::path(s.scene.file).filename().c_str(), o.size, o.size, o.threads);
    const Reference ref = reference_of(s, o, o.reference_spp, "chapter 06, MIS");
    std::vector<TimedRmse> forward;
    std::vector<double> fs, fr;
    const LightTracer light(s.prepared.world, s.importance, s.prepared.lights, s.camera,
                            LightTracerOptions{});
    for (int spp : {4, 16, 64, 256}) {
        const RenderSettings settings = study_settings(o, spp);
        const SplatResult r = render_light_tracing(light, settings, paths_per_image(settings));
        forward.push_back({spp, compare(r.render.image, ref.image).rmse, r.render.seconds});
        fs.push_back(forward.back().seconds);
        fr.push_back(forward.back().rmse);
    }
    std::printf("%-22s %6s %12s %10s\n", "tracer", "spp", "RMSE", "time (s)");
    for (const TimedRmse& f : forward)
        std::printf("%-22s %6d %12.4e %10.4f\n", "forward (connect)", f.spp, f.rmse, f.seconds);
    std::ofstream csv;
    if (!o.csv.empty()) {
        csv.open(o.csv);
        if (!csv) throw InputError("--csv: " + o.csv + ": cannot be written");
        // One row per render, forward and reverse alike, in named columns; only a reverse row has the
        // forward time to its RMSE and the ratio.
        csv << "tracer,spp,rmse,seconds,forward_seconds_to_same_rmse,forward_over_reverse\n";
        for (const TimedRmse& f : forward)
            csv << "forward (connect)," << f.spp << ',' << f.rmse << ',' << f.seconds << ",,\n";
    }
    std::printf("\n%-22s %6s %12s %10s %18s %12s\n", "reverse (chapter 06)", "spp", "RMSE", "time (s)",
                "forward to same", "forward/rev.");
    for (SamplingStrategy strategy : {SamplingStrategy::kMis, SamplingStrategy::kBrdf}) {
        PathOptions options = PathOptions{};
        options.strategy = strategy;
        const PathTracer tracer(s.prepared.world, s.prepared.materials, s.prepared.lights, options);
        for (int spp : {4, 16, 64}) {
            const RenderResult r = render_paths(tracer, s.camera, study_settings(o, spp));
            const double rmse = compare(r.image, ref.image).rmse;
            const double t = time_to_rmse(fs, fr, rmse);
            std::printf("%-22s %6d %12.4e %10.4f %18.4f %12.2f\n",
                        (std::string("path tracer, ") + std::string(to_string(strategy))).c_str(), spp, rmse,
                        r.seconds, t, t / r.seconds);
            if (csv)
                csv << "reverse (" << to_string(strategy) << ")," << spp << ',' << rmse << ',' << r.seconds
                    << ',' << t << ',' << t / r.seconds << '\n';
        }
    }
}

void wins_and_losses(const StudyScene& s, const StudyOptions& o) {
    std::printf("\n3. Where forward tracing wins and loses (%s, %dx%d): RMSE per region of the image\n",
                std::filesystem::path(s.scene.file).filename().c_str(), o.size, o.size);
    // A scene with mirrors and glass: chapter 06's loop on chapter 07's materials (s.prepared's).
    const Reference ref = reference_of(s, o, o.glass_reference_spp, "chapter 07's path tracer");
    // The regions: pixels whose centre sees a mirror first; pixels the caustic lights (the light tracer's
    // caustic paths alone give at least 10% of the reference); the rest.
    LightTracerOptions caustic_options = LightTracerOptions{};
    caustic_options.paths = LightPathSet::kCaustics;
    const LightTracer caustic_tracer(s.prepared.world, s.importance, s.prepared.lights, s.camera,
                                     caustic_options);
    const RenderSettings caustic_settings = study_settings(o, 64);
    const Image caustic =
        render_light_tracing(caustic_tracer, caustic_settings, paths_per_image(caustic_settings))
            .render.image;
    const std::size_t n = ref.image.pixel_count();
    std::vector<std::uint8_t> mirror(n, 0), lit(n, 0), rest(n, 0);
    for (int y = 0; y < o.size; ++y) {
        for (int x = 0; x < o.size; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(o.size) + std::size_t(x);
            const auto hit =
                s.prepared.world.intersect(camera_ray(s.camera, Real(x) + Real(0.5), Real(y) + Real(0.5)));
            // Mirrors and smooth glass: delta BSDFs, which a pinhole cannot be connected to.
            if (hit && s.prepared.materials.bsdf(hit->material, hit->front_face).flags().delta)
                mirror[i] = 1;
            else if (luminance(caustic.pixels()[i]) >= Real(0.1) * luminance(ref.image.pixels()[i]) &&
                     luminance(caustic.pixels()[i]) > 0)
                lit[i] = 1;
            else
                rest[i] = 1;
        }
    }
    auto count = [](const std::vector<std::uint8_t>& m) {
        std::size_t c = 0;
        for (auto v : m) c += v;
        return c;
    };
    std::printf("  regions: caustic %zu pixels, mirror or glass %zu pixels, the rest %zu pixels\n",
                count(lit), count(mirror), count(rest));
    std::printf("%-22s %6s %10s %14s %14s %14s\n", "tracer", "spp", "time (s)", "RMSE caustic",
                "RMSE specular", "RMSE rest");
    // Render A of the reference against the mean: the reference's own RMSE, region by region.
    const Image a =
        read_pfm(std::filesystem::path(ref.file).replace_filename(ref.file.stem().string() + "_half.pfm"));
    std::printf("%-22s %6d %10s %14.4e %14.4e %14.4e\n", "reference's own noise", ref.spp, "",
                masked_rmse(a, ref.image, lit), masked_rmse(a, ref.image, mirror),
                masked_rmse(a, ref.image, rest));
    const LightTracer light(s.prepared.world, s.importance, s.prepared.lights, s.camera,
                            LightTracerOptions{});
    const PathTracer path(s.prepared.world, s.prepared.materials, s.prepared.lights, PathOptions{});
    for (int spp : {16, 64}) {
        const RenderSettings settings = study_settings(o, spp);
        const SplatResult f = render_light_tracing(light, settings, paths_per_image(settings));
        const RenderResult r = render_paths(path, s.camera, settings);
        for (const auto& [name, image, seconds] :
             {std::tuple{"forward (connect)", &f.render.image, f.render.seconds},
              std::tuple{"reverse (chapter 07)", &r.image, r.seconds}}) {
            std::printf("%-22s %6d %10.4f %14.4e %14.4e %14.4e\n", name, spp, seconds,
                        masked_rmse(*image, ref.image, lit), masked_rmse(*image, ref.image, mirror),
                        masked_rmse(*image, ref.image, rest));
        }
    }
}

}  // namespace

double masked_rmse(const Image& image, const Image& reference, const std::vector<std::uint8_t>& mask) {
    double sum = 0;
    std::size_t count = 0;
    for (std::size_t i = 0; i < mask.size(); ++i) {
        if (!mask[i]) continue;
        const Vec3d d = Vec3d(image.pixels()[i]) - Vec3d(reference.pixels()[i]);
        sum += glm::dot(d, d);
        count += 3;
    }
    return count > 0 ? std::sqrt(sum / double(count)) : 0.0;
}

double time_to_rmse(const std::vector<double>& seconds, const std::vector<double>& rmse, double target) {
    if (seconds.empty()) return 0;
    if (target >= rmse.front()) return seconds.front() * std::pow(rmse.front() / target, 2.0);
    for (std::size_t i = 1; i < seconds.size(); ++i) {
        if (target >= rmse[i]) {
            // log t linear in log RMSE between points i − 1 and i.
            const double a = std::log(rmse[i - 1] / target) / std::log(rmse[i - 1] / rmse[i]);
            return std::exp(std::log(seconds[i - 1]) + a * std::log(seconds[i] / seconds[i - 1]));
        }
    }
    return seconds.back() * std::pow(rmse.back() / target, 2.0);
}

void run_forward_study(const StudyOptions& options) {
    if (!std::filesystem::is_directory(options.cache))
        throw InputError("--cache: " + options.cache + ": not a folder");
    if (!options.csv.empty()) check_writable("--csv", options.csv);  // before any render
    const StudyScene cornell(load_scene(scene_path("ch06_default.json")), options.size, options.size);
    fractions(cornell, options);
    time_to_same_rmse(cornell, options);
    for (const char* file : {"ch08_default.json", "ch08_mirror.json"}) {
        const StudyScene scene(load_scene(scene_path(file)), options.size, options.size);
        wins_and_losses(scene, options);
    }
}

StudyScene::StudyScene(Scene s, int width, int height)
    : scene(std::move(s)),
      prepared(scene, EffectSet::all(), refraction_materials()),
      importance(scene, EffectSet::all(), refraction_materials(Transport::kImportance)),
      camera(make_pinhole_camera(scene.camera, width, height)) {}

}  // namespace rt
