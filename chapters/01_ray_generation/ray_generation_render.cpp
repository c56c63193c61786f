#include "ray_generation_render.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>

#include "camera_render.hpp"
#include "direction_shading.hpp"
#include "rt/io/image_io.hpp"

namespace rt {
namespace {

template <typename Shade>
RenderResult render_with(const PinholeCamera& camera, PixelSampler sampler, const RenderSettings& settings,
                         Shade shade) {
    return render_camera_rays(camera, sampler, settings,
                              [&](const Ray& ray, Pcg32&, RayCounts&) { return shade(ray.direction); });
}

}  // namespace

RenderResult render_directions(const PinholeCamera& camera, const FilmEdge& edge, PixelSampler sampler,
                               const RenderSettings& settings) {
    return render_with(camera, sampler, settings, [&](const Vec3& d) {
        return inside(edge, d) ? direction_colour(d) : sky_gradient(d);
    });
}

RenderResult render_coverage(const PinholeCamera& camera, const FilmEdge& edge, PixelSampler sampler,
                             const RenderSettings& settings) {
    return render_with(camera, sampler, settings,
                       [&](const Vec3& d) { return Color(inside(edge, d) ? Real(1) : Real(0)); });
}

double edge_rmse(const Image& coverage, const FilmEdge& edge) {
    double squared = 0;
    long count = 0;
    for (int y = 0; y < coverage.height(); ++y) {
        for (int x = 0; x < coverage.width(); ++x) {
            const double exact = exact_coverage(edge, x, y);
            if (exact <= 0 || exact >= 1) continue;
            const double d = double(coverage.at(x, y).r) - exact;
            squared += d * d;
            ++count;
        }
    }
    return count > 0 ? std::sqrt(squared / double(count)) : 0.0;
}

std::vector<AntialiasingRow> antialiasing_study(const PinholeCamera& camera, const FilmEdge& edge,
                                                RenderSettings settings, const std::vector<int>& spp_values) {
    std::vector<AntialiasingRow> rows;
    for (PixelSampler sampler : {PixelSampler::kCenter, PixelSampler::kUniform, PixelSampler::kStratified}) {
        for (int spp : spp_values) {
            if (sampler == PixelSampler::kCenter && spp > 1) continue;  // every centre sample is the same
            settings.samples_per_pixel = spp;
            const RenderResult r = render_coverage(camera, edge, sampler, settings);
            rows.push_back({sampler, spp, edge_rmse(r.image, edge), r.seconds});
        }
    }
    return rows;
}

void run_antialiasing_study(const PinholeCamera& camera, const FilmEdge& edge, const RenderSettings& settings,
                            const std::string& csv) {
    if (!csv.empty()) check_writable("--csv", csv);
    const auto rows = antialiasing_study(camera, edge, settings, {1, 4, 16, 64, 256});
    std::printf("anti-aliasing on a straight edge, %dx%d, %d threads: RMSE of pixel coverage over the edge\n",
                settings.width, settings.height, settings.threads);
    std::printf("%-11s %5s %12s %10s\n", "sampler", "spp", "edge RMSE", "time (s)");
    std::ofstream out;
    if (!csv.empty()) {
        out.open(csv);
        out << "sampler,spp,edge_rmse,seconds\n";
    }
    for (const AntialiasingRow& row : rows) {
        std::printf("%-11s %5d %12.5f %10.4f\n", to_string(row.sampler).data(), row.spp, row.edge_rmse,
                    row.seconds);
        if (out) {
            out << to_string(row.sampler) << ',' << row.spp << ',' << row.edge_rmse << ',' << row.seconds
                << '\n';
        }
    }
}

}  // namespace rt
