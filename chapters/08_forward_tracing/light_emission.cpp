#include "light_emission.hpp"

#include <cmath>

#include "02_intersection/float_error.hpp"
#include "04_direct_lighting/frame.hpp"
#include "04_direct_lighting/sampling.hpp"
#include "06_monte_carlo/warp_pdfs.hpp"

namespace rt {
namespace {

// The cosine-weighted direction about n and the throughput β₀ = π Le / (P pdf_A) it gives.
void emit_lambertian(EmissionSample& s, Vec2 u_direction) {
    const Vec3 local = sample_cosine_hemisphere(u_direction);
    s.direction = glm::normalize(make_frame(s.origin.normal).to_world(local));
    s.beta = kPi * s.position_weight;
}

}  // namespace

EmitterSampler::EmitterSampler(const LightSet& lights) : picker_(lights) {}

std::optional<EmissionSample> EmitterSampler::sample(Real u_pick, Vec2 u_point, Vec2 u_direction) const {
    if (picker_.empty()) return std::nullopt;
    std::size_t i = picker_.pick(u_pick);
    // A light of zero power shares its cdf value with the one before it and is never picked.
    const Real P = probability(i);
    if (!(P > 0)) return std::nullopt;
    EmissionSample s;
    const auto& quads = picker_.quads();
    const auto& triangles = picker_.triangles();
    const auto& spheres = picker_.spheres();
    if (i < quads.size()) {
        const QuadLight& q = quads[i];
        const Vec3 a = u_point.x * q.u, b = u_point.y * q.v;
        s.origin.point = q.origin + a + b;
        // x = Q + a u + b v: three rounded operations per component.
        s.origin.point_error = gamma_bound(3) * (abs(q.origin) + abs(a) + abs(b));
        s.origin.normal = q.normal;
        s.position_weight = q.radiance * (q.area / P);
        emit_lambertian(s, u_direction);
        return s;
    }
    i -= quads.size();
    if (i < triangles.size()) {
        const TriangleLight& t = triangles[i];
        const Vec2 bary = sample_uniform_triangle(u_point);
        const Vec3 a = (1 - bary.x - bary.y) * t.p0, b = bary.x * t.p1, c = bary.y * t.p2;
        s.origin.point = a + b + c;
        s.origin.point_error = gamma_bound(7) * (abs(a) + abs(b) + abs(c));
        s.origin.normal = t.normal;
        s.position_weight = t.radiance * (t.area / P);
        emit_lambertian(s, u_direction);
        return s;
    }
    i -= triangles.size();
    if (i < spheres.size()) {
        const SphereLight& sp = spheres[i];
        const Vec3 w = sample_uniform_sphere(u_point);
        s.origin.point = sp.center + sp.radius * w;
        s.origin.point_error = gamma_bound(5) * (abs(sp.center) + abs(sp.radius * w));
        s.origin.normal = w;
        s.position_weight = sp.radiance * (4 * kPi * sp.radius * sp.radius / P);
        emit_lambertian(s, u_direction);
        return s;
    }
    i -= spheres.size();
    const PointLight& p = picker_.points()[i];
    s.point_light = true;
    s.origin.point = p.position;
    s.position_weight = p.intensity / P;
    s.direction = glm::normalize(sample_uniform_sphere(u_direction));
    s.origin.normal = s.direction;
    s.beta = 4 * kPi * s.position_weight;
    return s;
}

}  // namespace rt
