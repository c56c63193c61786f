#include "walk_study.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "04_direct_lighting/render_scene.hpp"
#include "homogeneous_medium.hpp"
#include "media_materials.hpp"
#include "media_scenes.hpp"
#include "rt/core/error_metrics.hpp"
#include "volume_path_tracer.hpp"

namespace rt {

std::vector<WalkLengthRow> walk_lengths(const std::vector<double>& mean_free_paths,
                                        const std::vector<double>& albedos, int paths, std::uint64_t seed) {
    std::vector<WalkLengthRow> rows;
    for (double mfp : mean_free_paths) {
        for (double albedo : albedos) {
            const Real sigma_t = Real(1 / mfp);
            const Scene scene =
                medium_sphere_scene({Color(sigma_t * Real(1 - albedo)), Color(sigma_t * Real(albedo)), 0});
            const RenderScene prepared(scene, EffectSet::all(), media_materials());
            const VolumePathTracer tracer(prepared.world, prepared.materials, prepared.lights, PathOptions{},
                                          {1 << 30, true});
            WalkLengthRow row{mfp, albedo, 0, 0, 0, 0};
            double events = 0, radiance = 0;
            const auto start = std::chrono::steady_clock::now();
            for (int i = 0; i < paths; ++i) {
                Pcg32 rng = Pcg32::for_sample(0, std::uint64_t(i), seed);
                RayCounts rays;
                // Straight at the sphere, at a uniform point of its disc: every path enters it.
                const Real r = std::sqrt(rng.next_real()) * Real(0.999), phi = 2 * kPi * rng.next_real();
                const Ray ray{{r * std::cos(phi), r * std::sin(phi), 4}, {0, 0, -1}};
                radiance += double(luminance(tracer.radiance(ray, rng, rays)));
                // Each scattering event in the medium spawns one ray of kind indirect (no surface here
                // scatters diffusely).
                events += double(rays[RayKind::kIndirect]);
                row.longest = std::max(row.longest, rays[RayKind::kIndirect]);
            }
            const double seconds =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            row.events_per_path = events / paths;
            row.ns_per_path = seconds * 1e9 / paths;
            row.radiance = radiance / paths;
            rows.push_back(row);
        }
    }
    return rows;
}

std::vector<WalkKnobRow> walk_knobs(const Scene& scene, const RenderSettings& settings,
                                    const PathOptions& options, const Image& reference,
                                    const std::vector<int>& caps) {
    std::vector<WalkKnobRow> rows;
    for (bool roulette : {true, false}) {
        for (int cap : caps) {
            const RenderResult r =
                render_with_media(Renderer::kPaths, scene, options.simulated, settings, options, {cap, roulette});
            const ErrorMetrics e = compare(r.image, reference);
            rows.push_back({cap, roulette, e.rmse, e.mean_error, r.seconds});
        }
    }
    return rows;
}

std::vector<FreeFlightRow> free_flight_study(const Color& sigma_t, Real t_max,
                                             const std::vector<int>& samples, int trials,
                                             std::uint64_t seed) {
    Color exact;
    for (int c = 0; c < 3; ++c) exact[c] = 1 - std::exp(-sigma_t[c] * t_max);
    std::vector<FreeFlightRow> rows;
    for (int n : samples) {
        FreeFlightRow row{n, 0, 0, 0, 0};
        // Spectral MIS divides the weight by the mean of the channels' densities relative to the chosen
        // one's; the naive estimate keeps the weight as it is.
        for (bool mis : {true, false}) {
            double squared = 0, max_weight = 0;
            for (int trial = 0; trial < trials; ++trial) {
                Pcg32 rng = Pcg32::for_sample(std::uint64_t(trial), std::uint64_t(n), seed);
                Color sum(0);
                for (int i = 0; i < n; ++i) {
                    const int channel = pick_channel(rng.next_real());
                    const FreeFlight f =
                        sample_free_flight(sigma_t, sigma_t, t_max, channel, rng.next_real());
                    if (!f.scattered) continue;
                    const Real mean = (f.pdf_ratio.r + f.pdf_ratio.g + f.pdf_ratio.b) / 3;
                    const Color w = mis ? f.weight / mean : f.weight;
                    sum += w;
                    max_weight = std::max(max_weight, double(std::max({w.r, w.g, w.b})));
                }
                for (int c = 0; c < 3; ++c) {
                    const double relative = (double(sum[c]) / n - exact[c]) / exact[c];
                    squared += relative * relative / 3;
                }
            }
            const double rms = std::sqrt(squared / trials);
            if (mis) {
                row.rms_error_average = rms;
                row.max_weight_average = max_weight;
            } else {
                row.rms_error_chosen = rms;
                row.max_weight_chosen = max_weight;
            }
        }
        rows.push_back(row);
    }
    return rows;
}

}  // namespace rt
