// Sampling a planar light by area. A point x is drawn uniformly on the light (density 1 / A per unit area);
// seen from p, the solid angle dω = |cos θ_l| dA / d² (θ_l between the light's normal and the direction back
// to p, d = |x − p|), so the direction's density is pdf_ω = d² / (|cos θ_l| A).
#pragma once

#include <optional>

#include "area_lights.hpp"
#include "light_sample.hpp"

namespace rt {

// The area density converted to solid angle: d² / (cos θ_l A); +∞ would be returned for cos θ_l = 0, so
// callers drop such samples (they carry no light: the light is seen edge-on).
inline Real area_to_solid_angle_pdf(Real distance, Real cos_light, Real area) {
    return distance * distance / (cos_light * area);
}

// The picker's density for a direction wi that met a planar light of radiance L at distance d and cosine
// cos θ_l: P(light) pdf_light = (lum(L) A / W) (d² / (cos θ_l A)) = lum(L) d² / (cos θ_l W), W the picker's
// total weight. The area cancels: MIS weighs a BSDF sample that hit a quad or a triangle knowing only the
// emitter's radiance, its distance and its cosine.
inline Real picked_planar_pdf(const Color& radiance, Real distance, Real cos_light, Real total_weight) {
    return luminance(radiance) * distance * distance / (cos_light * total_weight);
}

// x = origin + u₁ U + u₂ V (the solid-angle sampler hands it the coordinates it chose, so this map is the
// contract), with the solid-angle density of its direction. Nothing when p is behind the light (it emits
// one-sided) or sees it edge-on.
std::optional<LightSample> sample_quad_light(const QuadLight& light, const Vec3& p, Vec2 u);
// The solid-angle density with which sample_quad_light picks direction wi from p (0 if wi misses the light).
Real quad_light_pdf(const QuadLight& light, const Vec3& p, const Vec3& wi);

// x = (1 − b1 − b2) p0 + b1 p1 + b2 p2 with (b1, b2) uniform on the triangle.
std::optional<LightSample> sample_triangle_light(const TriangleLight& light, const Vec3& p, Vec2 u);

}  // namespace rt
