// The solid angle a rectangle subtends, and directions drawn uniformly in it (Ureña, Fajardo and King, "An
// Area-Preserving Parametrization for Spherical Rectangles", EGSR 2013). Seen from p, a rectangle with corner
// s and perpendicular edges U, V projects onto the unit sphere as a spherical rectangle. In the frame
// x = U/|U|, y = V/|V|, z = x × y it spans [x0, x1] × [y0, y1] in the plane z = z0 < 0 (p on the side z
// points to). Its corners' directions v_ij = (x_i, y_j, z0) bound it by four great circles, with normals
//   n0 ∝ v00 × v10,  n1 ∝ v10 × v11,  n2 ∝ v11 × v01,  n3 ∝ v01 × v00,
// interior angles γ_k = arccos(−n_k · n_{k+1}), and area (Girard's theorem)
//   Ω = γ0 + γ1 + γ2 + γ3 − 2π.
// A uniform direction (pdf = 1 / Ω) is found by inverting two CDFs in closed form: x from the area of the
// part left of x, then y from h = y / √(x² + y² + z0²), which is uniform along the vertical line at x.
// Computed in double: Ω is a small difference of angles near 2π.
#pragma once

#include <optional>

#include "rt/core/math.hpp"

namespace rt {

class SphericalRectangle {
  public:
    // Nothing when p lies in the rectangle's plane or behind it (the side −z), or an edge is degenerate. U
    // and V must be perpendicular (the caller checks: a parallelogram has no such closed form).
    static std::optional<SphericalRectangle> seen_from(const Vec3& p, const Vec3& corner, const Vec3& U,
                                                       const Vec3& V);

    // Ω in steradians.
    double solid_angle() const { return solid_angle_; }
    // The point hit by the direction u ∈ [0, 1)² warps to, as fractions (a, b) of U and V: x = s + a U + b V.
    Vec2 sample(Vec2 u) const;

  private:
    double x0_ = 0, x1_ = 0, y0_ = 0, y1_ = 0, z0_ = 0;
    double b0_ = 0, b1_ = 0, k_ = 0;  // n0.z, n2.z, 2π − γ2 − γ3
    double solid_angle_ = 0;
};

}  // namespace rt
