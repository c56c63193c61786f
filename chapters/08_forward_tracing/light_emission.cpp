#include "light_emission.hpp"

#include <cmath>
#include <typeindex>
#include <unordered_map>

#include "01_ray_generation/concentric_disk.hpp"
#include "02_intersection/float_error.hpp"
#include "04_direct_lighting/distant_emitter.hpp"
#include "04_direct_lighting/frame.hpp"
#include "04_direct_lighting/point_emitter.hpp"
#include "04_direct_lighting/quad_emitter.hpp"
#include "04_direct_lighting/sampling.hpp"
#include "04_direct_lighting/sphere_emitter.hpp"
#include "04_direct_lighting/spot_emitter.hpp"
#include "04_direct_lighting/triangle_emitter.hpp"
#include "06_monte_carlo/warp_pdfs.hpp"

namespace rt {
namespace {

// The start of a light path from a light picked with probability P: a point from u_point, a direction from
// u_direction.
using Emission = EmissionSample (*)(const Light& light, Real P, Vec2 u_point, Vec2 u_direction);

// The cosine-weighted direction about n and the throughput β₀ = π Le / (P pdf_A) it gives.
void emit_lambertian(EmissionSample& s, Vec2 u_direction) {
    const Vec3 local = sample_cosine_hemisphere(u_direction);
    s.direction = glm::normalize(make_frame(s.origin.normal).to_world(local));
    s.beta = kPi * s.position_weight;
}

// u_direction for the side a light emits from: its front, or for a two-sided light either side with
// probability 1/2 (u.x picks it and is stretched back to [0, 1); β₀ doubles).
Vec2 pick_side(EmissionSample& s, bool two_sided, Vec2 u) {
    if (!two_sided) return u;
    s.position_weight *= 2;
    if (u.x < Real(0.5)) return {2 * u.x, u.y};
    s.origin.normal = -s.origin.normal;
    return {2 * u.x - 1, u.y};
}

EmissionSample from_quad(const Light& light, Real P, Vec2 u_point, Vec2 u_direction) {
    const QuadLight& q = static_cast<const QuadEmitter&>(light).quad();
    EmissionSample s;
    const Vec3 a = u_point.x * q.u, b = u_point.y * q.v;
    s.origin.point = q.origin + a + b;
    // x = Q + a u + b v: three rounded operations per component.
    s.origin.point_error = gamma_bound(3) * (abs(q.origin) + abs(a) + abs(b));
    s.origin.normal = q.normal;
    s.position_weight = q.radiance * (q.area / P);
    emit_lambertian(s, pick_side(s, q.two_sided, u_direction));
    return s;
}

EmissionSample from_triangle(const Light& light, Real P, Vec2 u_point, Vec2 u_direction) {
    const TriangleLight& t = static_cast<const TriangleEmitter&>(light).triangle();
    EmissionSample s;
    const Vec2 bary = sample_uniform_triangle(u_point);
    const Vec3 a = (1 - bary.x - bary.y) * t.p0, b = bary.x * t.p1, c = bary.y * t.p2;
    s.origin.point = a + b + c;
    s.origin.point_error = gamma_bound(7) * (abs(a) + abs(b) + abs(c));
    s.origin.normal = t.normal;
    s.position_weight = t.radiance * (t.area / P);
    emit_lambertian(s, pick_side(s, t.two_sided, u_direction));
    return s;
}

EmissionSample from_sphere(const Light& light, Real P, Vec2 u_point, Vec2 u_direction) {
    const SphereLight& sp = static_cast<const SphereEmitter&>(light).sphere();
    EmissionSample s;
    const Vec3 w = sample_uniform_sphere(u_point);
    s.origin.point = sp.center + sp.radius * w;
    s.origin.point_error = gamma_bound(5) * (abs(sp.center) + abs(sp.radius * w));
    s.origin.normal = w;
    s.position_weight = sp.radiance * (4 * kPi * sp.radius * sp.radius / P);
    emit_lambertian(s, u_direction);
    return s;
}

EmissionSample from_point(const Light& light, Real P, Vec2, Vec2 u_direction) {
    const PointLight& p = static_cast<const PointEmitter&>(light).point();
    EmissionSample s;
    s.delta_light = true;
    s.origin.point = p.position;
    s.position_weight = p.intensity / P;
    s.direction = glm::normalize(sample_uniform_sphere(u_direction));
    s.origin.normal = s.direction;
    s.beta = 4 * kPi * s.position_weight;
    return s;
}

// A spot: from its point, a direction uniform in its cone (pdf_ω = 1 / (2π (1 − cos θ_end))), carrying its
// falloff: β₀ = I falloff / (P pdf_ω).
EmissionSample from_spot(const Light& light, Real P, Vec2, Vec2 u_direction) {
    const auto& spot = static_cast<const SpotEmitter&>(light);
    EmissionSample s;
    s.delta_light = true;
    s.origin.point = spot.spot().position;
    s.position_weight = spot.spot().intensity / P;
    const Real one_minus_cos_end = 1 - spot.cos_end();
    const Vec3 local = sample_uniform_cone(u_direction, one_minus_cos_end);
    s.direction = glm::normalize(make_frame(spot.axis()).to_world(local));
    s.origin.normal = s.direction;
    s.beta = s.position_weight * (spot.falloff(s.direction) * 2 * kPi * one_minus_cos_end);
    return s;
}

// A distant light: a point uniform on the disk of the scene's radius r, facing the light, r before the
// scene's centre (pdf_A = 1 / (π r²)), sent along the light's direction: β₀ = E π r² / P.
EmissionSample from_distant(const Light& light, Real P, Vec2 u_point, Vec2) {
    const auto& distant = static_cast<const DistantEmitter&>(light);
    const Vec3& d = distant.light().direction;
    const BoundingSphere& scene = distant.scene();
    const Vec2 disk = scene.radius * sample_disk_concentric(u_point);
    EmissionSample s;
    s.delta_light = true;
    s.origin.point = scene.center + make_frame(d).to_world(Vec3(disk, -scene.radius));
    s.direction = d;
    s.origin.normal = d;
    s.position_weight = distant.light().irradiance * (kPi * scene.radius * scene.radius / P);
    s.beta = s.position_weight;
    return s;
}

// Each Light class this chapter traces forward, with how it emits.
Emission emission_of(const Light& light) {
    static const std::unordered_map<std::type_index, Emission> by_class{
        {typeid(QuadEmitter), from_quad},       {typeid(TriangleEmitter), from_triangle},
        {typeid(SphereEmitter), from_sphere},   {typeid(PointEmitter), from_point},
        {typeid(DistantEmitter), from_distant}, {typeid(SpotEmitter), from_spot},
    };
    const auto found = by_class.find(typeid(light));
    return found == by_class.end() ? nullptr : found->second;
}

// `lights` with only the lights traced forward (the picker here asks no density: no Hit::light numbering).
LightSet traced_lights(const LightSet& lights) {
    LightSet traced;
    for (const auto& light : lights.lights) {
        if (emission_of(*light)) traced.lights.push_back(light);
    }
    return traced;
}

}  // namespace

bool traced_forward(const Light& light) {
    return emission_of(light) != nullptr;
}

EmitterSampler::EmitterSampler(const LightSet& lights) : picker_(traced_lights(lights)) {}

std::optional<EmissionSample> EmitterSampler::sample(Real u_pick, Vec2 u_point, Vec2 u_direction) const {
    if (picker_.empty()) return std::nullopt;
    const std::size_t i = picker_.pick(u_pick);
    // A light of zero power shares its cdf value with the one before it and is never picked.
    const Real P = probability(i);
    if (!(P > 0)) return std::nullopt;
    const Light& light = picker_.light(i);
    return emission_of(light)(light, P, u_point, u_direction);
}

}  // namespace rt
