// Equiangular distance sampling (Kulla and Fajardo, EGSR 2012): along a ray segment [0, t_max) in a medium,
// a distance t drawn toward a point x_l on a light, with density proportional to the inverse square law
// that the light's contribution follows there, 1 / |x(t) − x_l|²:
//   Δ = (x_l − o) · d              the foot of x_l on the ray (d unit),
//   D = |x_l − (o + Δ d)|          the distance of x_l from the ray's line,
//   |x(t) − x_l|² = D² + (t − Δ)²,
//   θ(t) = atan((t − Δ) / D)       the angle under which x_l sees x(t): dθ/dt = D / (D² + (t − Δ)²),
//   pdf(t) = D / (w (D² + (t − Δ)²)),   w = θ(t_max) − θ(0):
// t is uniform in the angle θ, hence the name. The robust forms below (not the naive ones of the paper):
//   D from the perpendicular vector, not √(|x_l − o|² − Δ²) (which cancels to 0 or a negative number when x_l
//     is near the line and far from o);
//   w = atan2(D t_max, D² − Δ (t_max − Δ)) (atan b − atan a = atan2(b − a, 1 + ab)), not the difference of
//     two angles that are both ±π/2 in floating point when x_l is near the line beyond the segment;
//   t = (D² + Δ²) τ / (D + Δ τ), τ = tan(u w) (the tangent addition formula applied to θ(0) + u w), exact at
//     u = 0, with no tan of an angle near ±π/2.
#pragma once

#include <optional>

#include "rt/core/math.hpp"
#include "rt/core/ray.hpp"

namespace rt {

class EquiangularSampler {
  public:
    // The sampler over [0, t_max) of `ray` (unit direction) toward `light_point`. None when t_max is not
    // finite and positive (a medium's segment ends at the next surface; open fog is not sampled this way), or
    // when the light lies on the ray's line (D = 0: the density would be a spike at Δ).
    static std::optional<EquiangularSampler> toward(const Ray& ray, const Vec3& light_point, Real t_max);

    // t in [0, t_max) from u in [0, 1).
    Real sample(Real u) const;
    // pdf(t) on [0, t_max); 0 outside.
    Real pdf(Real t) const;

    Real distance() const { return d_; }  // D

  private:
    EquiangularSampler(Real delta, Real d, Real width, Real t_max)
        : delta_(delta), d_(d), width_(width), t_max_(t_max) {}
    Real delta_, d_, width_, t_max_;
};

}  // namespace rt
