#include "ray_generation_render.hpp"

#include <cmath>

#include "camera_render.hpp"
#include "direction_shading.hpp"

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

}  // namespace rt
