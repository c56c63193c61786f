// Chapter 04's direction samplers as warps for the chi-square test of chi_square.hpp (header-only, shared by the
// test programs of chapters 04 and 06): the bare warps of sampling.hpp with their pdfs, and the light samplers
// with the solid-angle densities of their directions. Chapter 04's tests fit each one; chapter 06's check them
// all at the ends of [0, 1).
#pragma once

#include <cmath>
#include <functional>
#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "04_direct_lighting/area_light_sampling.hpp"
#include "04_direct_lighting/frame.hpp"
#include "04_direct_lighting/quad_light_strategy.hpp"
#include "04_direct_lighting/sampling.hpp"
#include "04_direct_lighting/sphere_light_sampling.hpp"
#include "chi_square.hpp"

namespace rt::test {

// The solid-angle density with which sample_triangle_light picks wi from p: d² / (cos θ_l A) where the ray
// meets the triangle's plane inside its edges, else 0. Computed in double, with the edges widened by 1e-6, so
// that a sample on an edge (u = 0 gives one) is not lost to the rounding of its own point.
inline double triangle_light_pdf(const TriangleLight& light, const Vec3& p, const Vec3& wi) {
    const Vec3d n(light.normal), d(wi), o(p), a(light.p0), b(light.p1), c(light.p2);
    const double cos_light = -glm::dot(n, d);
    if (!(cos_light > 0)) return 0;
    const double t = glm::dot(n, a - o) / glm::dot(n, d);
    if (!(t > 0)) return 0;
    const Vec3d x = o + t * d;
    const Vec3d normal = glm::cross(b - a, c - a);
    const double inverse = 1 / glm::dot(normal, normal);
    const double b1 = glm::dot(glm::cross(x - a, c - a), normal) * inverse;
    const double b2 = glm::dot(glm::cross(b - a, x - a), normal) * inverse;
    if (b1 < -1e-6 || b2 < -1e-6 || b1 + b2 > 1 + 1e-6) return 0;
    return t * t / (cos_light * double(light.area));
}

// The warps under test: name, sampler (with the pdf it reports), pdf (each in its local frame).
struct Warp {
    std::string name;
    DirectionSampler sample;
    DirectionPdf pdf;
};

// A bare warp reports the pdf its pdf function gives.
inline Warp bare(std::string name, std::function<Vec3(Vec2)> warp, DirectionPdf pdf) {
    return {std::move(name),
            [=](Vec2 u) {
                const Vec3 w = warp(u);
                return Drawn{w, pdf(w)};
            },
            pdf};
}

// A light sampler reports its LightSample's pdf (0 and no direction when it gives none).
inline Drawn drawn(const std::optional<LightSample>& s) {
    return s ? Drawn{s->wi, double(s->pdf)} : Drawn{Vec3(0), 0.0};
}

inline Warp uniform_hemisphere_warp() {
    return bare("uniform hemisphere", sample_uniform_hemisphere,
                [](const Vec3& d) { return double(uniform_hemisphere_pdf(d)); });
}

inline Warp cosine_hemisphere_warp() {
    return bare("cosine hemisphere", sample_cosine_hemisphere,
                [](const Vec3& d) { return double(cosine_hemisphere_pdf(d.z)); });
}

inline std::vector<Warp> cone_warps() {
    std::vector<Warp> w;
    for (double degrees : {20.0, 60.0, 150.0}) {
        const Real one_minus_cos = Real(1 - std::cos(degrees * std::numbers::pi / 180));
        w.push_back(bare(
            "cone " + std::to_string(int(degrees)) + " degrees",
            [=](Vec2 u) { return sample_uniform_cone(u, one_minus_cos); },
            [=](const Vec3& d) { return double(uniform_cone_pdf(d, one_minus_cos)); }));
    }
    return w;
}

inline std::vector<Warp> power_cosine_warps() {
    std::vector<Warp> w;
    for (Real e : {0.0f, 6.0f, 48.0f}) {
        w.push_back(bare(
            "power cosine e = " + std::to_string(int(e)), [=](Vec2 u) { return sample_power_cosine(u, e); },
            [=](const Vec3& d) { return double(power_cosine_pdf(d.z, e)); }));
    }
    return w;
}

// The quad light of the tests, 0.5 above p = 0 (so that it fills a large solid angle), and its directions
// from p by area (sample_quad_light) or by solid angle (spherical rectangles).
inline QuadLight near_quad_light() {
    return make_quad_light({-1, -0.5f, 0.5f}, {0, 1.5f, 0}, {2, 0, 0}, Color(1));
}

inline Warp quad_light_warp(std::string name, const QuadLight& quad, QuadLightSampling by) {
    return {std::move(name), [=](Vec2 u) { return drawn(sample_quad_light(quad, Vec3(0), u, by)); },
            [=](const Vec3& d) { return double(quad_light_pdf(quad, Vec3(0), d, by)); }};
}

// Points on a triangle light close above p = 0, seen as directions.
inline Warp triangle_light_warp() {
    const TriangleLight triangle =
        make_triangle_light({-1, -1, 0.7f}, {0.5f, 1.5f, 0.3f}, {1.5f, -1, 0.4f}, Color(1));
    return {"triangle light directions", [=](Vec2 u) { return drawn(sample_triangle_light(triangle, Vec3(0), u)); },
            [=](const Vec3& d) { return triangle_light_pdf(triangle, Vec3(0), d); }};
}

// A sphere light seen from p = 0, sampled by its cone.
inline Warp sphere_light_warp() {
    const SphereLight sphere{{0.3f, 0.4f, 1.2f}, 0.6f, Color(1)};
    return {"sphere light directions", [=](Vec2 u) { return drawn(sample_sphere_light(sphere, Vec3(0), u)); },
            [=](const Vec3& d) {
                // Uniform in the cone: sphere_light_pdf inside it, 0 outside.
                const Vec3 axis = glm::normalize(sphere.center);
                const Real ratio = sphere.radius / glm::length(sphere.center);
                const Real cone = one_minus_cos_stable(ratio * ratio);
                return uniform_cone_pdf(make_frame(axis).to_local(d), cone) > 0
                           ? double(sphere_light_pdf(sphere, Vec3(0)))
                           : 0.0;
            }};
}

// Points on a quad, a triangle and a sphere light, seen as directions.
inline std::vector<Warp> light_warps() {
    return {quad_light_warp("quad light directions", near_quad_light(), QuadLightSampling::kArea),
            triangle_light_warp(), sphere_light_warp()};
}

// Quads sampled by solid angle (spherical rectangles): the quad of light_warps, and a 4 x 4 lamp 0.3 above p
// (Ω = 5.45 sr), where directions reach 82 degrees from the lamp's normal.
inline std::vector<Warp> solid_angle_quad_warps() {
    std::vector<Warp> w;
    for (const QuadLight& quad : {near_quad_light(), make_quad_light({-2, -2, 0.3f}, {0, 4, 0}, {4, 0, 0}, Color(1))})
        w.push_back(quad_light_warp("quad light directions by solid angle, area " + std::to_string(quad.area), quad,
                                    QuadLightSampling::kSolidAngle));
    return w;
}

// The chi-square test of each warp against its pdf, which must integrate to 1, at `level` (sidak_level of the
// program's count), with seeds first_seed, first_seed + 1, … (each warp its own).
inline void require_warps_fit(const std::vector<Warp>& group, std::uint64_t first_seed, double level) {
    std::uint64_t seed = first_seed;
    for (const Warp& w : group) {
        INFO(w.name);
        require_fit(test_directions(w.sample, w.pdf, seed++), level);
    }
}

}  // namespace rt::test
