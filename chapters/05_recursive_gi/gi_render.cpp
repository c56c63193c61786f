#include "gi_render.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>

#include "01_ray_generation/camera_render.hpp"
#include "rt/core/error_metrics.hpp"

namespace rt {
namespace {

constexpr int kRepeats = 3;

}  // namespace

RenderResult render_gi(const RecursiveTracer& tracer, const PinholeCamera& camera,
                       const RenderSettings& settings) {
    return render_camera_rays(
        camera, PixelSampler::kStratified, settings,
        [&](const Ray& ray, Pcg32& rng, RayCounts& rays) { return tracer.radiance(ray, rng, rays); });
}

std::string describe(const TerminationSettings& t) {
    char text[96];
    switch (t.rule) {
        case Termination::kMaxDepth:
            std::snprintf(text, sizeof text, "depth %d", t.max_depth);
            break;
        case Termination::kMinThroughput:
            std::snprintf(text, sizeof text, "throughput %g (cap %d)", double(t.min_throughput), t.max_depth);
            break;
        case Termination::kRussianRoulette:
            std::snprintf(text, sizeof text, "roulette from %d (cap %d)", t.roulette_start_depth,
                          t.max_depth);
            break;
    }
    return text;
}

std::vector<DepthStudyRow> depth_study(const World& world, const Scene& scene, const Furnace& furnace,
                                       const PinholeCamera& camera, const RenderSettings& settings,
                                       const std::vector<TerminationSettings>& rules, DirectOptions direct) {
    // The furnace's light reaches the camera after any number of bounces: indirect light always.
    direct.simulated.insert(Effect::kIndirect);
    const MaterialTable materials(scene, direct.simulated);
    const DirectLighting shading(world, materials, collect_lights(scene), direct);
    const Vec3d exact3 = furnace_radiance(furnace);
    const double exact = (exact3.x + exact3.y + exact3.z) / 3;
    const Image exact_image = furnace_image(furnace, settings.width, settings.height);
    std::vector<DepthStudyRow> rows;
    for (const TerminationSettings& termination : rules) {
        const RecursiveTracer tracer(shading, GiOptions{termination});
        // The same render kRepeats times (the same image each time): the median time resists the machine's
        // noise.
        RenderResult r;
        std::vector<double> seconds;
        for (int i = 0; i < kRepeats; ++i) {
            r = render_gi(tracer, camera, settings);
            seconds.push_back(r.seconds);
            if (r.interrupted) return rows;  // Ctrl-C: the rows so far
        }
        std::sort(seconds.begin(), seconds.end());
        DepthStudyRow row;
        row.termination = termination;
        row.light_sampling = direct.simulates(Effect::kDirect);
        double sum = 0, sum2 = 0;
        for (const Color& c : r.image.pixels()) {
            const double m = (double(c.r) + double(c.g) + double(c.b)) / 3;
            sum += m;
            sum2 += m * m;
        }
        const double n = double(r.image.pixel_count());
        row.mean = sum / n;
        row.standard_error = std::sqrt(std::max(0.0, sum2 / n - row.mean * row.mean) / (n - 1));
        // Roulette is unbiased up to its cap, so its expectation is the cap's truncation, as for max depth.
        if (termination.rule == Termination::kMinThroughput) {
            row.expected = std::numeric_limits<double>::quiet_NaN();
        } else {
            const Vec3d e = furnace_radiance_truncated(furnace, termination.max_depth);
            row.expected = (e.x + e.y + e.z) / 3;
        }
        row.exact = exact;
        row.bias = row.mean - exact;
        row.rmse = compare(r.image, exact_image).rmse;
        row.seconds = seconds[seconds.size() / 2];
        const double camera_rays = double(r.rays[RayKind::kCamera]);
        row.rays_per_path = camera_rays > 0 ? double(r.rays.total()) / camera_rays : 0;
        rows.push_back(row);
    }
    return rows;
}

void print_depth_study(const std::vector<DepthStudyRow>& rows, const Scene& scene, const Furnace& furnace,
                       const RenderSettings& settings, const std::string& csv) {
    std::printf(
        "termination rules in the furnace: %s, albedo %.3g, emission %.3g, exact L = Le / (1 - rho) = %.6g\n"
        "%dx%d, %d spp, seed %llu, %d threads; bias = mean - exact (+- its standard error), RMSE over "
        "pixels\n",
        scene.file.c_str(), double(furnace.albedo.g), double(furnace.emission.g),
        rows.empty() ? 0 : rows[0].exact, settings.width, settings.height, settings.samples_per_pixel,
        static_cast<unsigned long long>(settings.seed), settings.threads);
    std::printf("%-28s %-8s %10s %10s %10s %10s %10s %10s %9s\n", "rule", "lights", "mean", "expected",
                "bias", "std.error", "RMSE", "time (s)", "rays/path");
    std::ofstream out;
    if (!csv.empty()) {
        out.open(csv);
        out << "rule,max_depth,min_throughput,roulette_start,light_sampling,mean,expected,exact,bias,"
               "standard_error,rmse,seconds,"
               "rays_per_path\n";
    }
    for (const DepthStudyRow& r : rows) {
        char expected[32] = "-";
        if (!std::isnan(r.expected)) std::snprintf(expected, sizeof expected, "%.5f", r.expected);
        std::printf("%-28s %-8s %10.5f %10s %+10.5f %10.5f %10.5f %10.4f %9.2f\n",
                    describe(r.termination).c_str(), r.light_sampling ? "sampled" : "hit", r.mean, expected,
                    r.bias, r.standard_error, r.rmse, r.seconds, r.rays_per_path);
        if (out) {
            out << to_string(r.termination.rule) << ',' << r.termination.max_depth << ','
                << r.termination.min_throughput << ',' << r.termination.roulette_start_depth << ','
                << (r.light_sampling ? "sampled" : "hit") << ',' << r.mean << ','
                << (std::isnan(r.expected) ? std::string() : std::to_string(r.expected)) << ',' << r.exact
                << ',' << r.bias << ',' << r.standard_error << ',' << r.rmse << ',' << r.seconds << ','
                << r.rays_per_path << '\n';
        }
    }
}

}  // namespace rt
