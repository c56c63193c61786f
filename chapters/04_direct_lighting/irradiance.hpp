// Exact irradiance E(p) = ∫ L cos θ dω from uniform emitters of radiance L, for measuring error. Computed in
// double: they are references.
#pragma once

#include <span>

#include "rt/core/math.hpp"

namespace rt {

// Lambert's formula (1760) for a polygon v_0 … v_{k−1} seen from p with unit normal n:
//   E = (L / 2) |Σ_i Θ_i (n · Γ_i)|,  Θ_i = angle between v_i − p and v_{i+1} − p,
//   Γ_i = unit((v_i − p) × (v_{i+1} − p)).
// The polygon is first clipped to the half-space n · (x − p) >= 0 (the part below p's horizon sends no
// light). The polygon must be planar and convex; which side of it emits is the caller's business.
double polygon_irradiance(std::span<const Vec3d> vertices, const Vec3d& p, const Vec3d& n, double radiance);

// A sphere of radius r whose centre is at distance d from p, at angle θ from p's normal, fully above the
// horizon (θ + asin(r / d) <= π/2): E = π L (r / d)² cos θ (it acts like a point light of intensity π r² L).
double sphere_irradiance(double radiance, double radius, double distance, double cos_theta);

// A disc of radius R facing p at height h on p's normal (coaxial): E = π L R² / (R² + h²).
double coaxial_disc_irradiance(double radiance, double radius, double height);

// A uniform sky of radiance L over the whole hemisphere: E = π L.
double sky_irradiance(double radiance);

}  // namespace rt
