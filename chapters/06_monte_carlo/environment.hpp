// The environment light as the path tracer samples it: one light type, a constant radiance or an image.
//   constant: L(ω) = L; at a surface, cosine-weighted about the normal, p(ω) = cos θ / π (chapter 04's), and
//             uniform over the sphere at a point in a medium (no normal), p(ω) = 1 / 4π;
//   image:    L(ω) = scale · the pixel the lat-long map (lat_long_map.hpp) puts at ω, drawn by importance:
//             a Distribution2D over the pixels with weights luminance · sin θ (the solid angle of the pixel's
//             band), then p(ω) = p(u, v) / (2π² sin θ), the same anywhere in the scene.
// The MIS weight of light a path meets needs the density the next-event estimate would have drawn it with:
// pdf(normal, ω).
#pragma once

#include <memory>

#include "distribution_2d.hpp"
#include "lat_long_map.hpp"
#include "rt/core/image.hpp"
#include "rt/core/math.hpp"
#include "rt/core/scene.hpp"

namespace rt {

struct EnvironmentSample {
    Vec3 wi{0};
    Real pdf = 0;  // 0: no direction (the estimate skips it)
    Color radiance{0};
};

class Environment {
  public:
    explicit Environment(const EnvironmentLight& light);

    // No light at all: a black constant, or an image whose every pixel is black.
    bool black() const { return black_; }

    // The radiance arriving from direction `w` (unit), that is, of a ray leaving the scene along w.
    Color radiance(const Vec3& w) const {
        if (!image_) return constant_;
        return pixel(map_.point(w).uv);
    }
    // A direction toward the environment from a point with `normal` (Vec3(0): a point in a medium).
    EnvironmentSample sample(const Vec3& normal, Vec2 u) const;
    // The density sample() draws `w` with from a point with `normal`.
    Real pdf(const Vec3& normal, const Vec3& w) const;

  private:
    Color pixel(Vec2 uv) const;

    Color constant_;
    std::shared_ptr<const Image> image_;
    Real scale_ = 1;
    LatLongMap map_;
    std::shared_ptr<const Distribution2D> distribution_;  // shared: a tracer's copies share one table
    bool black_ = false;
};

}  // namespace rt
