// Every sampler the chi-square tests fit, by name, with the parameters a student may turn (and one mistake,
// for class: a pdf without its Jacobian): the warps of chapter 04 (direction_warps.hpp, shared with chapters
// 04 and 06's tests), the BRDFs chapter 06 samples, chapter 07's rough glass and metal, chapter 09's
// Henyey–Greenstein phase function and equiangular distances. The sampler view
// (chapters/09_participating_media/sampler_view) draws whichever a student picks; tests/sampler_view_test.cpp
// fits them. Each comes from the chapters' code, so in the student edition it is the student's own.
#pragma once

#include <cmath>
#include <functional>
#include <memory>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "04_direct_lighting/brdf.hpp"
#include "06_monte_carlo/warp_pdfs.hpp"
#include "07_bsdf_refraction/conductor.hpp"
#include "07_bsdf_refraction/rough_dielectric.hpp"
#include "09_participating_media/equiangular.hpp"
#include "09_participating_media/henyey_greenstein.hpp"
#include "direction_warps.hpp"
#include "rt/core/conductor_presets.hpp"

namespace rt::test {

// A number a student may set, within [min, max]: the range the harness's 48 × 96 cells resolve (a lobe or a
// cone much narrower than a cell is beyond them).
struct SamplerParameter {
    std::string name;
    std::string meaning;
    double min, max, value;  // value: the default
};

struct RegisteredSampler {
    std::string name;     // "power_cosine"
    std::string chapter;  // "04"
    std::string title;    // what it samples, and the function that does
    std::vector<SamplerParameter> parameters;
    // The warp for these parameter values (in the order of `parameters`); `seed` seeds a BSDF's choice of
    // lobe.
    std::function<Warp(const std::vector<double>& values, std::uint64_t seed)> make;
    bool may_lose = false;  // a BSDF whose samples may leave on the wrong side (require_fit_with_losses)
    // Instead of `make`, for a sampler of distances along a segment: its warp for these parameter values.
    std::function<SegmentWarp(const std::vector<double>& values)> make_segment = nullptr;
};

inline Real radians(double degrees) {
    return Real(degrees * std::numbers::pi / 180);
}

// A BSDF's sample() as a warp at wo about n: u from the harness, u_lobe from its own generator; a sample with
// pdf 0 is lost.
inline Warp bsdf_warp(std::string name, std::shared_ptr<const Bsdf> bsdf, Vec3 wo, Vec3 n,
                      std::uint64_t seed) {
    auto lobe = std::make_shared<Pcg32>(seed, 23);
    return {std::move(name),
            [=](Vec2 u) {
                const BsdfSample s = bsdf->sample(wo, n, u, lobe->next_real());
                return Drawn{s.wi, double(s.pdf), !(s.pdf > 0)};
            },
            [=](const Vec3& wi) { return double(bsdf->pdf(wo, wi, n)); }};
}

// wo at `degrees` from n = +z, turned 0.4 about it (chapter 06's BRDF tests).
inline Warp brdf_warp(std::string name, std::shared_ptr<const Bsdf> brdf, double degrees,
                      std::uint64_t seed) {
    const Real theta = radians(degrees);
    const Vec3 wo(std::sin(theta) * std::cos(0.4f), std::sin(theta) * std::sin(0.4f), std::cos(theta));
    return bsdf_warp(std::move(name), std::move(brdf), wo, Vec3(0, 0, 1), seed);
}

// wo at `degrees` from n = +x, in the x–y plane (chapter 07's tests: both lobes on the grid's equator).
inline Warp side_warp(std::string name, std::shared_ptr<const Bsdf> bsdf, double degrees,
                      std::uint64_t seed) {
    const Real theta = radians(degrees);
    return bsdf_warp(std::move(name), std::move(bsdf), Vec3(std::cos(theta), std::sin(theta), 0),
                     Vec3(1, 0, 0), seed);
}

// A sampler without parameters.
inline RegisteredSampler fixed(std::string name, std::string chapter, std::string title, Warp (*warp)()) {
    return {std::move(name),
            std::move(chapter),
            std::move(title),
            {},
            [warp](const std::vector<double>&, std::uint64_t) { return warp(); }};
}

// A mistake to find, for class (chapter 01's lesson): θ and φ drawn uniformly over the upper hemisphere, and
// as the pdf per steradian the density of (θ, φ), 1 / π², without the Jacobian sin θ of dω = sin θ dθ dφ (the
// right pdf is 1 / (π² sin θ)). The samples crowd the pole, and the pdf integrates to 2 / π.
inline Warp missing_jacobian_warp() {
    return bare(
        "theta uniform",
        [](Vec2 u) {
            const double theta = double(u.x) * std::numbers::pi / 2, phi = 2 * std::numbers::pi * double(u.y);
            return Vec3(Real(std::sin(theta) * std::cos(phi)), Real(std::sin(theta) * std::sin(phi)),
                        Real(std::cos(theta)));
        },
        [](const Vec3& d) { return d.z >= 0 ? 1 / (std::numbers::pi * std::numbers::pi) : 0.0; });
}

// The parameters of the BSDF samplers.
inline const SamplerParameter kIncidentAngle{"incident_angle", "degrees between wo and the normal", 0, 89,
                                             30};
inline const SamplerParameter kRoughness{"roughness", "0.1 (sharp) to 1 (broad)", 0.1, 1, 0.3};

// Chapter 04's warps and light samplers (direction_warps.hpp).
inline std::vector<RegisteredSampler> chapter04_samplers() {
    return {
        fixed("uniform_hemisphere", "04", "uniform hemisphere (sample_uniform_hemisphere)",
              uniform_hemisphere_warp),
        fixed("cosine_hemisphere", "04", "cosine-weighted hemisphere (sample_cosine_hemisphere)",
              cosine_hemisphere_warp),
        {"uniform_cone",
         "04",
         "uniform cone about +z (sample_uniform_cone)",
         {{"half_angle", "degrees", 10, 180, 60}},
         [](const std::vector<double>& v, std::uint64_t) {
             const Real one_minus_cos = Real(1 - std::cos(double(radians(v[0]))));
             return bare(
                 "uniform cone", [=](Vec2 u) { return sample_uniform_cone(u, one_minus_cos); },
                 [=](const Vec3& d) { return double(uniform_cone_pdf(d, one_minus_cos)); });
         }},
        {"power_cosine",
         "04",
         "power-cosine lobe cos^e about +z (sample_power_cosine)",
         {{"exponent", "e: 0 is uniform, 1 the cosine, larger narrower", 0, 200, 6}},
         [](const std::vector<double>& v, std::uint64_t) {
             const Real e = Real(v[0]);
             return bare(
                 "power cosine", [=](Vec2 u) { return sample_power_cosine(u, e); },
                 [=](const Vec3& d) { return double(power_cosine_pdf(d.z, e)); });
         }},
        fixed("quad_light", "04", "directions to a quad light by area (sample_quad_light)",
              [] { return quad_light_warp("quad light", near_quad_light(), QuadLightSampling::kArea); }),
        fixed(
            "quad_light_solid_angle", "04", "directions to a quad light by solid angle (spherical rectangle)",
            [] { return quad_light_warp("quad light", near_quad_light(), QuadLightSampling::kSolidAngle); }),
        fixed("triangle_light", "04", "directions to a triangle light (sample_triangle_light)",
              triangle_light_warp),
        fixed("sphere_light", "04", "directions to a sphere light by its cone (sample_sphere_light)",
              sphere_light_warp),
    };
}

// Chapter 06's uniform sphere, and the BRDFs it samples: wo at incident_angle from n = +z.
inline std::vector<RegisteredSampler> chapter06_samplers() {
    const Color albedo(0.7f);
    return {
        fixed("uniform_sphere", "06", "uniform sphere (sample_uniform_sphere)",
              [] {
                  return bare("uniform sphere", sample_uniform_sphere,
                              [](const Vec3&) { return double(kUniformSpherePdf); });
              }),
        {"lambert_brdf",
         "06",
         "Lambert BRDF's sample() (cosine-weighted)",
         {kIncidentAngle},
         [=](const std::vector<double>& v, std::uint64_t seed) {
             return brdf_warp("lambert", std::make_shared<LambertBrdf>(albedo), v[0], seed);
         }},
        {"glossy_brdf",
         "06",
         "glossy (modified Phong) BRDF's sample()",
         {kRoughness, kIncidentAngle},
         [=](const std::vector<double>& v, std::uint64_t seed) {
             return brdf_warp("glossy", std::make_shared<GlossyBrdf>(albedo, phong_exponent(Real(v[0]))),
                              v[1], seed);
         }},
        {"retroreflective_brdf",
         "06",
         "retroreflective BRDF's sample()",
         {kRoughness, kIncidentAngle},
         [=](const std::vector<double>& v, std::uint64_t seed) {
             return brdf_warp("retro",
                              std::make_shared<RetroreflectiveBrdf>(albedo, phong_exponent(Real(v[0]))), v[1],
                              seed);
         }},
    };
}

// Chapter 07's rough glass and metal: wo at incident_angle from n = +x.
// Rough glass of index eta seen from outside (power 1: η = eta) or from inside (power −1: η = 1 / eta), as
// chapter 07's tests try both. An index within 0.2 of 1 is not offered: its refracted lobe is then narrower
// than the harness's cells resolve.
inline RegisteredSampler rough_glass(std::string name, const std::string& side, int power) {
    return {std::move(name),
            "07",
            "rough glass, " + side + ": GGX visible normals, reflection or refraction (normal +x)",
            {kRoughness, {"eta", "the glass's index of refraction", 1.2, 3, 1.5}, kIncidentAngle},
            [power](const std::vector<double>& v, std::uint64_t seed) {
                const Real eta = Real(std::pow(v[1], power));
                return side_warp("rough glass",
                                 std::make_shared<RoughDielectric>(Real(v[0]), eta, Transport::kRadiance),
                                 v[2], seed);
            },
            true};
}

inline std::vector<RegisteredSampler> chapter07_samplers() {
    return {
        rough_glass("rough_dielectric", "entering", 1),
        rough_glass("rough_dielectric_inside", "leaving: wo inside the glass", -1),
        {"rough_conductor",
         "07",
         "rough gold: GGX visible normals, reflection (normal +x)",
         {kRoughness, kIncidentAngle},
         [](const std::vector<double>& v, std::uint64_t seed) {
             const ConductorPreset& gold = kConductorPresets[0];
             return side_warp("rough metal", std::make_shared<Conductor>(gold.eta, gold.k, Real(v[0])), v[1],
                              seed);
         },
         true},
    };
}

// Chapter 09's phase function and distances, and chapter 01's mistake.
inline std::vector<RegisteredSampler> chapter09_samplers() {
    return {
        {"henyey_greenstein",
         "09",
         "Henyey-Greenstein phase function, travelling along +x (sample)",
         {{"g", "mean cosine: < 0 backward, > 0 forward", -0.95, 0.95, 0.3}},
         [](const std::vector<double>& v, std::uint64_t) {
             const auto phase = std::make_shared<HenyeyGreenstein>(Real(v[0]));
             const Vec3 wo(-1, 0, 0);
             return Warp{"henyey-greenstein",
                         [=](Vec2 u) {
                             const PhaseSample s = phase->sample(wo, u);
                             return Drawn{s.wi, double(s.pdf)};
                         },
                         [=](const Vec3& w) { return double(phase->eval(wo, w)); }};
         }},
        {"equiangular",
         "09",
         "equiangular distances on a ray of length 10 toward a point light (EquiangularSampler)",
         {{"delta", "where the light's foot lies on the ray", -10, 20, 3},
          {"distance", "the light's distance from the ray", 0.05, 5, 0.5}},
         nullptr,
         false,
         [](const std::vector<double>& v) {
             constexpr Real kLength = 10;
             // D >= 0.05: the light is off the ray's line, so there is a sampler.
             const auto sampler = *EquiangularSampler::toward(Ray{{0, 0, 0}, {0, 0, 1}},
                                                              Vec3(Real(v[1]), 0, Real(v[0])), kLength);
             return SegmentWarp{"equiangular", kLength,
                                [=](double u) { return double(sampler.sample(Real(u))); },
                                [=](double t) { return double(sampler.pdf(Real(t))); }};
         }},
        fixed("mistake_missing_jacobian", "01",
              "a mistake to find: theta uniform, its pdf without sin(theta)", missing_jacobian_warp),
    };
}

// Every sampler, chapter by chapter, in the order the page lists them.
inline std::vector<RegisteredSampler> sampler_registry() {
    std::vector<RegisteredSampler> all;
    for (auto chapter : {chapter04_samplers, chapter06_samplers, chapter07_samplers, chapter09_samplers})
        for (RegisteredSampler& s : chapter()) all.push_back(std::move(s));
    return all;
}

}  // namespace rt::test
