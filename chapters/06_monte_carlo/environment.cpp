#include "environment.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "04_direct_lighting/frame.hpp"
#include "04_direct_lighting/sampling.hpp"
#include "warp_pdfs.hpp"

namespace rt {
namespace {

// w(i, j) = luminance · sin θ_j, θ_j at the centre of row j: the pixel's radiance times the solid angle of
// its cell (2π² sin θ du dv).
std::shared_ptr<const Distribution2D> importance_of(const Image& image) {
    const int w = image.width(), h = image.height();
    std::vector<double> weights(std::size_t(w) * std::size_t(h));
    for (int j = 0; j < h; ++j) {
        const double sin_theta = std::sin(std::numbers::pi * (j + 0.5) / h);
        for (int i = 0; i < w; ++i)
            weights[std::size_t(j) * std::size_t(w) + std::size_t(i)] =
                std::max(0.0, double(luminance(image.at(i, j)))) * sin_theta;
    }
    return std::make_shared<const Distribution2D>(weights, w, h);
}

}  // namespace

Environment::Environment(const EnvironmentLight& light)
    : constant_(light.radiance), image_(light.image), scale_(light.scale),
      map_(LatLongMap::turned_by_degrees(light.rotate_y)) {
    if (!image_) {
        black_ = is_black(constant_);
        return;
    }
    distribution_ = importance_of(*image_);
    black_ = !(distribution_->integral() > 0) || !(scale_ > 0);
}

Color Environment::pixel(Vec2 uv) const {
    const int x = std::min(int(uv.x * Real(image_->width())), image_->width() - 1);
    const int y = std::min(int(uv.y * Real(image_->height())), image_->height() - 1);
    return scale_ * image_->at(x, y);
}

EnvironmentSample Environment::sample(const Vec3& normal, Vec2 u) const {
    EnvironmentSample s;
    if (!image_) {
        if (normal == Vec3(0)) {
            s.wi = sample_uniform_sphere(u);
            s.pdf = kUniformSpherePdf;
        } else {
            s.wi = glm::normalize(make_frame(normal).to_world(sample_cosine_hemisphere(u)));
            s.pdf = cosine_hemisphere_pdf(glm::dot(s.wi, normal));
        }
        s.radiance = constant_;
        return s;
    }
    // The cell drawn, then its direction; the density and radiance are those pdf() and radiance() give that
    // direction, so the two strategies MIS weighs agree on it even where float puts it in the next cell.
    // At v = 0 (sin θ = 0) the density is 0 and the sample skipped, never infinite.
    s.wi = map_.direction(distribution_->sample(u).uv);
    s.pdf = pdf(normal, s.wi);
    if (s.pdf > 0) s.radiance = radiance(s.wi);
    return s;
}

Real Environment::pdf(const Vec3& normal, const Vec3& w) const {
    if (!image_) return normal == Vec3(0) ? kUniformSpherePdf : cosine_hemisphere_pdf(glm::dot(w, normal));
    const LatLongMap::Point p = map_.point(w);
    if (!(p.sin_theta > 0)) return 0;
    const int i = std::min(int(p.uv.x * Real(image_->width())), image_->width() - 1);
    const int j = std::min(int(p.uv.y * Real(image_->height())), image_->height() - 1);
    return distribution_->pdf(i, j) / (2 * kPi * kPi * p.sin_theta);
}

}  // namespace rt
