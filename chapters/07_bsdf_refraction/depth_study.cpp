#include "depth_study.hpp"

#include <cstdio>
#include <fstream>

#include "bsdf_render.hpp"
#include "rt/core/error_metrics.hpp"
#include "rt/core/errors.hpp"
#include "rt/io/image_io.hpp"

namespace rt {
namespace {

RenderResult render_glass(const Scene& scene, const RenderSettings& settings, const PathOptions& options) {
    return render_with(Renderer::kPaths, scene, options.simulated, settings, options);
}

}  // namespace

Image glass_depth_reference(const Scene& scene, const RenderSettings& settings, const PathOptions& options,
                            int spp, const std::filesystem::path& folder, bool& cached) {
    const std::filesystem::path file =
        folder / ("ch07_reference_" + std::filesystem::path(scene.file).stem().string() + "_" +
                  std::to_string(settings.width) + "x" + std::to_string(settings.height) + "_" +
                  std::to_string(spp) + "spp.pfm");
    if (std::filesystem::exists(file)) {
        Image image = read_pfm(file);
        if (image.width() == settings.width && image.height() == settings.height) {
            cached = true;
            return image;
        }
    }
    check_writable("--cache", file);
    RenderSettings s = settings;
    s.samples_per_pixel = spp;
    s.seed = settings.seed + 1000;  // independent of the renders it is compared with
    Image image = render_glass(scene, s, options).image;
    write_pfm(image, file);
    cached = false;
    return image;
}

std::vector<GlassDepthRow> glass_depth_study(const Scene& scene, const RenderSettings& settings,
                                             const PathOptions& options, const Image& reference,
                                             const std::vector<int>& depths) {
    std::vector<GlassDepthRow> rows;
    for (int depth : depths) {
        PathOptions o = options;
        o.termination = {Termination::kMaxDepth, depth};
        const RenderResult r = render_glass(scene, settings, o);
        const ErrorMetrics e = compare(r.image, reference);
        rows.push_back({depth, e.rmse, e.relative_mse, e.mean_error, r.seconds, r.rays.total()});
    }
    return rows;
}

void write_glass_depth_csv(const std::vector<GlassDepthRow>& rows, int spp, const std::filesystem::path& csv) {
    std::ofstream file(csv);
    if (!file) throw InputError("--csv: " + csv.string() + ": cannot be written");
    file << "max_depth,spp,rmse,relative_mse,mean_error,seconds,rays\n";
    for (const GlassDepthRow& r : rows)
        file << r.max_depth << ',' << spp << ',' << r.rmse << ',' << r.relative_mse << ',' << r.mean_error << ','
             << r.seconds << ',' << r.rays << '\n';
}

void run_glass_depth_study(const Scene& scene, const RenderSettings& settings, const PathOptions& options,
                           const GlassDepthRequest& request) {
    if (!request.csv.empty()) check_writable("--csv", request.csv);
    bool cached = false;
    std::printf("reference: %d spp, Russian roulette, %dx%d ...\n", request.reference_spp, settings.width,
                settings.height);
    std::fflush(stdout);
    const Image reference =
        glass_depth_reference(scene, settings, options, request.reference_spp, request.cache, cached);
    std::printf("  %s\n", cached ? "read from the cache" : "rendered and cached");
    const auto rows = glass_depth_study(scene, settings, options, reference, request.depths);
    std::printf("%9s %5s %12s %12s %12s %10s %12s\n", "max depth", "spp", "RMSE", "rel. MSE", "mean error",
                "time (s)", "rays");
    for (const GlassDepthRow& r : rows) {
        std::printf("%9d %5d %12.4e %12.4e %+12.4e %10.3f %12llu\n", r.max_depth, settings.samples_per_pixel,
                    r.rmse, r.relative_mse, r.mean_error, r.seconds, static_cast<unsigned long long>(r.rays));
    }
    if (!request.csv.empty()) write_glass_depth_csv(rows, settings.samples_per_pixel, request.csv);
}

}  // namespace rt
