// Chapter 04: direct lighting. The BRDFs (normalization, energy, reciprocity, sampling hooks), light sampling
// (points on the light, pdfs, the far sphere), the exact irradiance formulas against brute Monte Carlo, and
// renders: the analytic scene against its exact image, ray counts, and the default scene end to end.
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <functional>
#include <memory>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "01_ray_generation/camera.hpp"
#include "02_intersection/quad.hpp"
#include "02_intersection/sphere.hpp"
#include "02_intersection/triangle.hpp"
#include "04_direct_lighting/analytic_scene.hpp"
#include "04_direct_lighting/area_light_sampling.hpp"
#include "04_direct_lighting/brdf.hpp"
#include "04_direct_lighting/direct_render.hpp"
#include "04_direct_lighting/frame.hpp"
#include "04_direct_lighting/irradiance.hpp"
#include "04_direct_lighting/quad_emitter.hpp"
#include "04_direct_lighting/quad_light_strategy.hpp"
#include "04_direct_lighting/sampling.hpp"
#include "04_direct_lighting/sphere_emitter.hpp"
#include "04_direct_lighting/sphere_light_sampling.hpp"
#include "04_direct_lighting/spherical_rectangle.hpp"
#include "04_direct_lighting/texture.hpp"
#include "04_direct_lighting/triangle_emitter.hpp"
#include "random_unit.hpp"
#include "rt/core/error_metrics.hpp"
#include "rt/core/random.hpp"
#include "rt/io/assets.hpp"
#include "rt/io/image_io.hpp"
#include "rt/io/material_kind.hpp"
#include "rt/io/scene_loader.hpp"
#include "rt/io/scene_materials.hpp"
#include "support/chi_square.hpp"
#include "support/direction_warps.hpp"

using namespace rt;
using namespace rt::test;

namespace {

// The kind of each light of `lights`, in their order.
std::vector<std::string_view> kinds_of(const LightSet& lights) {
    std::vector<std::string_view> kinds;
    for (const auto& light : lights.lights) kinds.push_back(light->kind());
    return kinds;
}

// A Monte Carlo estimate: the mean of n samples and its standard error.
struct Estimate {
    double mean = 0;
    double error = 0;  // standard error of the mean
};

Estimate estimate(int n, const std::function<double()>& sample) {
    double sum = 0, sum2 = 0;
    for (int i = 0; i < n; ++i) {
        const double x = sample();
        sum += x;
        sum2 += x * x;
    }
    const double mean = sum / n;
    const double variance = std::max(0.0, sum2 / n - mean * mean);
    return {mean, std::sqrt(variance / n)};
}

// A unit direction at polar angle θ from +z (in the xz plane, turned by φ about z).
Vec3 polar(double theta, double phi = 0) {
    return Vec3(Real(std::sin(theta) * std::cos(phi)), Real(std::sin(theta) * std::sin(phi)),
                Real(std::cos(theta)));
}

// The BRDFs under test, each with a name, albedo 1 (the hardest case for energy conservation).
std::vector<std::pair<std::string, std::shared_ptr<const Bsdf>>> white_brdfs() {
    std::vector<std::pair<std::string, std::shared_ptr<const Bsdf>>> brdfs{
        {"lambert", std::make_shared<LambertBrdf>(Color(1))}};
    for (Real r : {0.05f, 0.2f, 0.5f, 1.0f}) {
        brdfs.push_back({"glossy roughness " + std::to_string(r),
                         std::make_shared<GlossyBrdf>(Color(1), phong_exponent(r))});
        brdfs.push_back({"retro roughness " + std::to_string(r),
                         std::make_shared<RetroreflectiveBrdf>(Color(1), phong_exponent(r))});
    }
    return brdfs;
}

const Vec3 kUp{0, 0, 1};

// Ten outgoing directions from normal incidence to 5° above the horizon.
std::vector<Vec3> ten_outgoing() {
    std::vector<Vec3> wo;
    for (int i = 0; i < 10; ++i) wo.push_back(polar(double(i) * radians(85) / 9, 0.3 * i));
    return wo;
}

Material diffuse(Color albedo, Color emission = Color(0)) {
    Material m;
    m.albedo = albedo;
    m.emission = emission;
    return m;
}

Shape shape(decltype(Shape::geometry) geometry, int material) {
    return Shape{geometry, material, "test"};
}

}  // namespace

// ---------------------------------------------------------------------------------------------------------
// BRDFs

namespace {

// ∫ f cos θ_i dω_i over the hemisphere for wo along the normal, by the midpoint rule over (cos θ, φ), where
// dω = d(cos θ) dφ: what a BRDF's normalization must make equal to its albedo.
double reflected_at_normal(const Bsdf& brdf) {
    constexpr int kCos = 20000, kPhi = 4;
    double sum = 0;
    for (int i = 0; i < kCos; ++i) {
        const double cos_theta = (i + 0.5) / kCos;
        for (int j = 0; j < kPhi; ++j) {
            const Vec3 wi = polar(std::acos(cos_theta), 2 * std::numbers::pi * (j + 0.5) / kPhi);
            sum += double(eval(brdf, kUp, wi, kUp).g) * cos_theta;
        }
    }
    return sum * 2 * std::numbers::pi / (double(kCos) * kPhi);
}

// The failure names the kind of mistake a reflected fraction `ratio` (of the albedo) points to.
std::string normalization_mistake(double ratio, double exponent) {
    std::ostringstream out;
    out << "the BRDF reflects " << ratio << " of its albedo, not all of it: the constant is not normalized "
        << "over the hemisphere (∫ f cos θ dω must be ρ)";
    if (std::abs(ratio - (exponent + 1) / (exponent + 2)) < 1e-3)
        out << "; this is the cosine left out of the normalization (∫ f dω = ρ, a density's constant)";
    return out.str();
}

}  // namespace

TEST_CASE("The Lambert BRDF is one constant above the surface that reflects all of its albedo, and 0 below",
          "[brdf][ex:ch04.lambert]") {
    const LambertBrdf lambert{Color(0.2f, 0.5f, 0.8f)};
    const Color f0 = eval(lambert, kUp, kUp, kUp);
    Pcg32 rng(1, 1);
    for (int i = 0; i < 1000; ++i) {
        Vec3 wo = random_unit(rng), wi = random_unit(rng);
        wo.z = std::abs(wo.z);
        wi.z = std::abs(wi.z);
        const Color f = eval(lambert, wo, wi, kUp);
        INFO("Lambert's f must not depend on the directions above the surface");
        REQUIRE(f.r == Approx(f0.r));
        REQUIRE(f.g == Approx(f0.g));
        REQUIRE(f.b == Approx(f0.b));
        CHECK(eval(lambert, wo, -wi, kUp) == Color(0));
        CHECK(eval(lambert, -wo, wi, kUp) == Color(0));
    }
    const LambertBrdf white{Color(1)};
    const double ratio = reflected_at_normal(white);
    INFO(normalization_mistake(ratio, 0));
    CHECK(ratio == Approx(1).epsilon(1e-4));
    // The albedo scales f channel by channel.
    CHECK(f0.r / f0.b == Approx(0.25));
    CHECK(f0.g / f0.b == Approx(0.625));
}

TEST_CASE("The glossy lobe about the normal reflects all of its albedo, for broad and sharp lobes",
          "[brdf][ex:ch04.glossy]") {
    for (const Real exponent : {0.0f, 1.0f, 6.0f, 48.0f, 1000.0f}) {
        INFO("exponent e = " << exponent);
        const double ratio = reflected_at_normal(GlossyBrdf{Color(1), exponent});
        INFO(normalization_mistake(ratio, exponent));
        CHECK(ratio == Approx(1).epsilon(1e-3));
    }
}

TEST_CASE("Every BRDF is reciprocal: f(a, b) = f(b, a)",
          "[brdf][ex:ch04.glossy][ex:ch04.lambert][ex:ch04.retroreflective]") {
    Pcg32 rng(2, 1);
    for (const auto& [name, owner] : white_brdfs()) {
        const Bsdf& brdf = *owner;
        INFO(name);
        for (int i = 0; i < 2000; ++i) {
            Vec3 a = random_unit(rng), b = random_unit(rng);
            a.z = std::abs(a.z);
            b.z = std::abs(b.z);
            // Half the pairs near each other, where the lobes are large.
            if (i % 2) b = glm::normalize(a + Real(0.3) * b);
            const Color fab = eval(brdf, a, b, kUp), fba = eval(brdf, b, a, kUp);
            REQUIRE(fab.r == Approx(fba.r).epsilon(1e-4).margin(1e-6));
        }
    }
}

TEST_CASE("Every BRDF conserves energy for ten outgoing directions",
          "[brdf][statistical][ex:ch04.cosine_hemisphere][ex:ch04.glossy][ex:ch04.lambert]"
          "[ex:ch04.power_cosine][ex:ch04.power_cosine_pdf][ex:ch04.retroreflective]"
          "[ex:ch04.uniform_hemisphere]") {
    // ∫ f cos θ_i dω_i estimated two ways with 2·10⁴ samples each: uniformly over the hemisphere (independent
    // of the BRDF's own sampling) and with the BRDF's sample(); both <= 1 within 4 standard errors, and they
    // agree with each other, which checks sample() and pdf().
    constexpr int kSamples = 20000;
    for (const auto& [name, owner] : white_brdfs()) {
        const Bsdf& brdf = *owner;
        int index = 0;
        for (const Vec3& wo : ten_outgoing()) {
            INFO(name << ", outgoing θ = " << std::acos(double(wo.z)) * 180 / std::numbers::pi << "°");
            Pcg32 uniform_rng(10, std::uint64_t(index)), brdf_rng(11, std::uint64_t(index++));
            const Estimate uniform = estimate(kSamples, [&] {
                const Vec3 wi = sample_uniform_hemisphere(uniform_rng.next_vec2());
                return double(eval(brdf, wo, wi, kUp).g * wi.z / kUniformHemispherePdf);
            });
            const Estimate sampled = estimate(kSamples, [&] {
                const BsdfSample s = sample(brdf, wo, kUp, brdf_rng.next_vec2());
                return s.pdf > 0 ? double(s.f.g * std::max(Real(0), s.wi.z) / s.pdf) : 0.0;
            });
            CHECK(uniform.mean <= 1 + 4 * uniform.error);
            CHECK(sampled.mean <= 1 + 4 * sampled.error + 1e-6);
            CHECK(std::abs(uniform.mean - sampled.mean) <=
                  4 * std::hypot(uniform.error, sampled.error) + 1e-6);
        }
    }
}

TEST_CASE("Lambert reflects all of albedo 1 and the lobes are normalized at normal incidence",
          "[brdf][statistical][ex:ch04.cosine_hemisphere][ex:ch04.glossy][ex:ch04.lambert]"
          "[ex:ch04.power_cosine][ex:ch04.power_cosine_pdf]") {
    // Not only <= 1: the normalization makes a lobe reflect exactly ρ when it lies wholly above the surface.
    // Estimated with the BRDF's own sampling.
    for (const auto& [name, owner] : white_brdfs()) {
        const Bsdf& brdf = *owner;
        INFO(name);
        const auto* glossy = dynamic_cast<const GlossyBrdf*>(&brdf);
        const auto* retro = dynamic_cast<const RetroreflectiveBrdf*>(&brdf);
        const bool wide = glossy && glossy->exponent < 10;
        const bool wide_retro = retro && retro->exponent < 10;
        if (wide || wide_retro) continue;  // a wide lobe around the normal is clipped by the horizon
        Pcg32 rng(12, 0);
        const Estimate e = estimate(20000, [&] {
            const BsdfSample s = sample(brdf, kUp, kUp, rng.next_vec2());
            return s.pdf > 0 ? double(s.f.g * std::max(Real(0), s.wi.z) / s.pdf) : 0.0;
        });
        CHECK(std::abs(e.mean - 1) <= 4 * e.error + 1e-3);
    }
}

TEST_CASE("sample() returns f and pdf equal to eval() and pdf() at the sampled direction",
          "[brdf][ex:ch04.cosine_hemisphere][ex:ch04.glossy][ex:ch04.lambert][ex:ch04.power_cosine]"
          "[ex:ch04.power_cosine_pdf][ex:ch04.retroreflective]") {
    Pcg32 rng(13, 0);
    for (const auto& [name, owner] : white_brdfs()) {
        const Bsdf& brdf = *owner;
        INFO(name);
        for (const Vec3& wo : ten_outgoing()) {
            for (int i = 0; i < 200; ++i) {
                const BsdfSample s = sample(brdf, wo, kUp, rng.next_vec2());
                REQUIRE(glm::length(s.wi) == Approx(1).epsilon(1e-5));
                REQUIRE_FALSE(s.delta);
                REQUIRE(s.pdf == Approx(pdf(brdf, wo, s.wi, kUp)).epsilon(1e-4));
                REQUIRE(s.f.g == Approx(eval(brdf, wo, s.wi, kUp).g).epsilon(1e-4));
            }
        }
    }
}

TEST_CASE("The mirror is a delta: light samples see 0, its one direction reflects R",
          "[brdf][ex:ch04.mirror]") {
    const MirrorBrdf mirror{Color(0.9f)};
    CHECK(is_delta(mirror));
    const Vec3 wo = glm::normalize(Vec3{1, 0, 1});
    // Even the exact mirror direction gives 0 through eval(): a delta has no finite value there.
    CHECK(eval(mirror, wo, reflect(wo, kUp), kUp) == Color(0));
    CHECK(pdf(mirror, wo, reflect(wo, kUp), kUp) == 0);
    Pcg32 rng(14, 0);
    for (int i = 0; i < 100; ++i) CHECK(eval(mirror, wo, random_unit(rng), kUp) == Color(0));
    const BsdfSample s = sample(mirror, wo, kUp, Vec2(0.5f));
    CHECK(s.delta);
    CHECK(s.wi.x == Approx(-wo.x));
    CHECK(s.wi.z == Approx(wo.z));
    // The reflected fraction is the reflectance, <= 1, at every angle (a grazing one too).
    for (const Real degrees : {0.0f, 20.0f, 45.0f, 70.0f, 89.0f}) {
        const Vec3 w = polar(radians(degrees));
        const BsdfSample t = sample(mirror, w, kUp, Vec2(0.5f));
        INFO("wo at " << degrees << " degrees: the weight f cos theta_i / pdf must be the reflectance R (a "
                                    "factor of the delta's f missing or extra)");
        CHECK(t.f.r * t.wi.z / t.pdf == Approx(0.9));
    }
}

TEST_CASE("Every BRDF is 0 when wo or wi is below the surface, even inside its lobe",
          "[brdf][ex:ch04.glossy][ex:ch04.lambert][ex:ch04.mirror][ex:ch04.retroreflective]") {
    // wo 80° from the normal; wi 95° from it, 15° from the glossy lobe's axis (on the far side) or from the
    // retro-reflective lobe's (on the near side): inside both lobes, but below the surface.
    const Vec3 wo = polar(radians(80)), far_below = polar(radians(95), kPi), near_below = polar(radians(95));
    for (const auto& [name, owner] : white_brdfs()) {
        INFO(name);
        const Bsdf& brdf = *owner;
        for (const Vec3& wi : {far_below, near_below}) {
            CHECK(eval(brdf, wo, wi, kUp) == Color(0));
            CHECK(eval(brdf, wi, wo, kUp) == Color(0));
        }
    }
    // A mirror seen from below the surface reflects nothing: its one direction is below too.
    const BsdfSample s = sample(MirrorBrdf{Color(0.9f)}, polar(radians(100)), kUp, Vec2(0.5f));
    CHECK(s.f == Color(0));
}

TEST_CASE("The Phong exponent follows roughness: 0 at roughness 1, sharp and finite near 0",
          "[brdf][stability][ex:ch04.glossy][ex:ch04.power_cosine][ex:ch04.power_cosine_pdf]") {
    CHECK(phong_exponent(1) == 0);
    CHECK(phong_exponent(Real(0.2)) == Approx(48));
    const Real sharp = phong_exponent(Real(1e-9));
    CHECK(std::isfinite(sharp));
    // A lobe sharper than float's resolution near cos α = 1 still samples directions off the axis.
    Pcg32 rng(15, 0);
    const GlossyBrdf glossy{Color(1), sharp};
    for (int i = 0; i < 100; ++i) {
        const BsdfSample s = sample(glossy, kUp, kUp, rng.next_vec2());
        REQUIRE(std::isfinite(s.pdf));
        REQUIRE(is_finite(s.f));
        REQUIRE(is_finite(s.wi));
    }
}

// ---------------------------------------------------------------------------------------------------------
// Sampling routines against their pdfs: chi-square goodness of fit (tests/support/chi_square.hpp), 10^6
// samples each, fixed seeds; and the narrow cones and sharp lobes where float cancels

namespace {

// Every chi-square test of this file (hemisphere 1, cosine 1, cones 3, lobes 3, lights 3, triangle 1, quads
// by solid angle 2, a narrow cone and a sharp lobe 2), each run at the Šidák-corrected level.
constexpr int kChiSquareTests = 16;
const double kAlphaPerTest = test::sidak_level(kChiSquareTests, 0.01);

}  // namespace

TEST_CASE("Uniform hemisphere directions fit uniform_hemisphere_pdf, which integrates to 1",
          "[statistical][ex:ch04.uniform_hemisphere][ex:ch04.uniform_hemisphere_pdf]") {
    require_warps_fit({uniform_hemisphere_warp()}, 101, kAlphaPerTest);
}

TEST_CASE("Cosine-weighted directions fit cosine_hemisphere_pdf, which integrates to 1",
          "[statistical][ex:ch04.cosine_hemisphere]") {
    require_warps_fit({cosine_hemisphere_warp()}, 102, kAlphaPerTest);
}

TEST_CASE("Directions in cones of 20, 60 and 150 degrees fit uniform_cone_pdf, which integrates to 1",
          "[statistical][ex:ch04.uniform_cone][ex:ch04.uniform_cone_pdf]") {
    require_warps_fit(cone_warps(), 104, kAlphaPerTest);
}

TEST_CASE("Power-cosine lobes of exponent 0, 6 and 48 fit power_cosine_pdf, which integrates to 1",
          "[statistical][ex:ch04.power_cosine][ex:ch04.power_cosine_pdf]") {
    require_warps_fit(power_cosine_warps(), 107, kAlphaPerTest);
}

TEST_CASE("Directions to a quad, a triangle and a sphere light fit their pdfs, which integrate to 1",
          "[statistical][ex:ch04.cone_solid_angle][ex:ch04.sample_quad_light][ex:ch04.uniform_cone]"
          "[ex:ch04.uniform_triangle][ex:ch04.uniform_cone_pdf]") {
    require_warps_fit(light_warps(), 110, kAlphaPerTest);
}

TEST_CASE("Directions to a quad by solid angle fit 1 / Omega, which integrates to 1, near and far",
          "[statistical][lights][solid_angle][ex:ch04.sample_quad_light]") {
    require_warps_fit(solid_angle_quad_warps(), 120, kAlphaPerTest);
}

TEST_CASE("Uniform points on a triangle: the barycentrics pass the chi-square test",
          "[statistical][ex:ch04.uniform_triangle]") {
    // Cells of a 40×40 grid over the unit square of (b1, b2); the density is 2 on the triangle b1 + b2 <= 1.
    constexpr int kSide = 40;
    std::vector<double> observed(kSide * kSide, 0), expected(kSide * kSide, 0);
    Pcg32 rng(300, 1);
    long long bad = 0;
    for (int s = 0; s < kDirectionSamples; ++s) {
        const Vec2 b = sample_uniform_triangle(rng.next_vec2());
        if (!(b.x >= 0 && b.y >= 0 && b.x + b.y <= 1 + 1e-6f)) {
            ++bad;
            continue;
        }
        const int i = std::min(kSide - 1, int(b.x * kSide)), j = std::min(kSide - 1, int(b.y * kSide));
        observed[std::size_t(i * kSide + j)] += 1;
    }
    // The part of cell (i, j) under the diagonal b1 + b2 = 1, exactly: all of it when its far corner is
    // under (i + j + 2 <= kSide), none when its near corner is on or above (i + j >= kSide), else half (the
    // diagonal runs corner to corner through it).
    for (int i = 0; i < kSide; ++i) {
        for (int j = 0; j < kSide; ++j) {
            const double inside = i + j + 2 <= kSide ? 1.0 : (i + j >= kSide ? 0.0 : 0.5);
            expected[std::size_t(i * kSide + j)] = kDirectionSamples * 2.0 * inside / (kSide * kSide);
        }
    }
    ChiSquare r = chi_square(observed, expected);
    INFO("chi-square " << r.statistic << ", " << r.dof << " dof, p = " << r.p_value);
    {
        INFO(kOutsideSupport);
        CHECK(bad == 0);
    }
    INFO(kHistogramDiffers);
    CHECK(r.p_value > kAlphaPerTest);
}

TEST_CASE("A narrow cone and a sharp lobe keep sin theta, and a narrow cone tells inside from outside",
          "[stability][ex:ch04.power_cosine][ex:ch04.uniform_cone][ex:ch04.uniform_cone_pdf]") {
    // A cone of half-angle 1e-3 (1 − cos θmax = 5e-7, a few ulps of 1 in float) and a lobe of exponent 10⁷.
    // Any correct inversion makes the fraction of the cone (1 − cos θ) / (1 − cos θmax), and the lobe's
    // cumulative distribution cos^(e+1) α, uniform on [0, 1]: read back from each direction's sin θ (in double,
    // 1 − cos θ = sin²θ / (1 + cos θ)), they pass the chi-square test in 100 equal cells only if sin θ kept its
    // digits; a sin θ from 1 − cos²θ in float takes a handful of values there.
    const double half_angle = 1e-3;
    const Real one_minus_cos_max = Real(2 * std::sin(half_angle / 2) * std::sin(half_angle / 2));
    const Real exponent = 1e7f;
    auto one_minus_cos = [](const Vec3& w) {
        const double sin2 = double(w.x) * double(w.x) + double(w.y) * double(w.y);
        return sin2 / (1 + std::sqrt(std::max(0.0, 1 - sin2)));
    };
    constexpr int kCells = 100, kSamples = 100000;
    std::vector<double> cone_cells(kCells, 0), lobe_cells(kCells, 0), expected(kCells, double(kSamples) / kCells);
    auto cell = [](double v) { return std::clamp(int(v * kCells), 0, kCells - 1); };
    Pcg32 rng(31, 4);
    long long outside = 0;
    for (int i = 0; i < kSamples; ++i) {
        const Vec2 u = rng.next_vec2();
        const Vec3 w = sample_uniform_cone(u, one_minus_cos_max);
        outside += !(uniform_cone_pdf(w, one_minus_cos_max) > 0);
        cone_cells[std::size_t(cell(one_minus_cos(w) / double(one_minus_cos_max)))] += 1;
        const double lobe_cdf = std::exp((double(exponent) + 1) * std::log1p(-one_minus_cos(
                                             sample_power_cosine(u, exponent))));
        lobe_cells[std::size_t(cell(lobe_cdf))] += 1;
    }
    {
        INFO(kOutsideSupport);
        CHECK(outside == 0);
    }
    const ChiSquare cone_fit = chi_square(cone_cells, expected), lobe_fit = chi_square(lobe_cells, expected);
    INFO("sin theta lost its digits (from 1 - cos^2 in float?), or a wrong inversion: chi-square of the cone "
         << cone_fit.statistic << " (p = " << cone_fit.p_value << "), of the lobe " << lobe_fit.statistic
         << " (p = " << lobe_fit.p_value << "), " << kCells - 1 << " dof");
    CHECK(cone_fit.p_value > kAlphaPerTest);
    CHECK(lobe_fit.p_value > kAlphaPerTest);
    // Directions inside and outside cones of half-angle 1e-3 and 3e-4 (1 − cos θmax = 4.5e-8, under one ulp of
    // 1: 1 − z in float is 0 or 6e-8 there, and only sin²θ / (1 + z) tells inside from outside).
    for (const double cone : {1e-3, 3e-4}) {
        const Real max = Real(2 * std::sin(cone / 2) * std::sin(cone / 2));
        for (const double fraction : {0.5, 0.9, 0.99, 1.01, 1.1}) {
            for (const double phi : {0.0, 1.0, 2.5}) {
                const double theta = fraction * cone;
                const Vec3 w(Real(std::sin(theta) * std::cos(phi)), Real(std::sin(theta) * std::sin(phi)),
                             Real(std::cos(theta)));
                INFO("cone " << cone << ", at " << fraction << " of it, phi " << phi);
                CHECK((uniform_cone_pdf(w, max) > 0) == (fraction < 1));
            }
        }
    }
}

TEST_CASE("The frame of every normal is orthonormal, also near minus z", "[stability]") {
    Pcg32 rng(16, 0);
    std::vector<Vec3> normals{
        {0, 0, 1}, {0, 0, -1}, glm::normalize(Vec3{1e-7f, 0, -1}), glm::normalize(Vec3{0, 1e-4f, -1})};
    for (int i = 0; i < 1000; ++i) normals.push_back(random_unit(rng));
    for (const Vec3& n : normals) {
        const Frame f = make_frame(n);
        REQUIRE(glm::length(f.t) == Approx(1).epsilon(1e-5));
        REQUIRE(glm::length(f.b) == Approx(1).epsilon(1e-5));
        REQUIRE(std::abs(glm::dot(f.t, f.b)) < 1e-5);
        REQUIRE(std::abs(glm::dot(f.t, f.n)) < 1e-5);
        REQUIRE(std::abs(glm::dot(f.b, f.n)) < 1e-5);
        REQUIRE(glm::dot(glm::cross(f.t, f.b), f.n) > 0.99f);  // right-handed
    }
}

// ---------------------------------------------------------------------------------------------------------
// Exact irradiance against brute Monte Carlo

namespace {

// E(p) = ∫ L cos θ dω by uniform hemisphere directions around n = +z, L where `sees_light` is true.
Estimate brute_irradiance(const Vec3& p, double radiance, const std::function<bool(const Ray&)>& sees_light,
                          std::uint64_t seed, int n = 100000) {
    Pcg32 rng(seed, 7);
    return estimate(n, [&] {
        const Vec3 wi = sample_uniform_hemisphere(rng.next_vec2());
        return sees_light(Ray{p, wi}) ? radiance * double(wi.z) / double(kUniformHemispherePdf) : 0.0;
    });
}

}  // namespace

TEST_CASE("Lambert's polygon formula matches brute Monte Carlo, also clipped by the horizon",
          "[irradiance][statistical][ex:ch02.quad][ex:ch02.triangle_watertight][ex:ch04.lambert_polygon]"
          "[ex:ch04.uniform_hemisphere]") {
    const Vec3 p{0.1f, -0.2f, 0};
    struct Case {
        const char* name;
        Vec3 origin, u, v;
    };
    const Case cases[] = {
        {"square above", {-0.5f, -0.5f, 1}, {1, 0, 0}, {0, 1, 0}},
        {"tilted, off to the side", {0.4f, -0.3f, 0.5f}, {0.8f, 0.1f, 0.2f}, {-0.1f, 0.3f, 0.9f}},
        {"crossing the horizon (clipped)", {-0.6f, 0.5f, -0.4f}, {1.2f, 0, 0}, {0, 0.2f, 1.2f}},
    };
    std::uint64_t seed = 20;
    for (const Case& c : cases) {
        INFO(c.name);
        const Quad quad = make_quad(c.origin, c.u, c.v);
        const std::array<Vec3d, 4> corners{Vec3d(c.origin), Vec3d(c.origin + c.u),
                                           Vec3d(c.origin + c.u + c.v), Vec3d(c.origin + c.v)};
        const double exact = polygon_irradiance(corners, Vec3d(p), Vec3d(kUp), 2.0);
        const Estimate brute = brute_irradiance(
            p, 2.0, [&](const Ray& r) { return bool(intersect_quad(r, quad, kInfinity)); }, seed++);
        CHECK(exact > 0);
        CHECK(std::abs(brute.mean - exact) <= 4 * brute.error);
    }
    // A triangle, given in either winding.
    const Triangle tri{{-1, 0.2f, 0.7f}, {0.6f, -0.4f, 1.1f}, {0.3f, 0.9f, 0.4f}};
    const std::array<Vec3d, 3> forward{Vec3d(tri.p0), Vec3d(tri.p1), Vec3d(tri.p2)};
    const std::array<Vec3d, 3> backward{Vec3d(tri.p2), Vec3d(tri.p1), Vec3d(tri.p0)};
    const double exact = polygon_irradiance(forward, Vec3d(p), Vec3d(kUp), 1.0);
    CHECK(polygon_irradiance(backward, Vec3d(p), Vec3d(kUp), 1.0) == Approx(exact));
    const Estimate brute = brute_irradiance(
        p, 1.0,
        [&](const Ray& r) { return bool(intersect_triangle(r, tri, kInfinity, TriangleTest::kWatertight)); },
        seed);
    CHECK(std::abs(brute.mean - exact) <= 4 * brute.error);
}

TEST_CASE("A long rectangle over p, whose edges subtend more than 90 degrees, gives the exact irradiance",
          "[irradiance][ex:ch04.lambert_polygon]") {
    // The rectangle [−a, a] × [−b, b] at height h over p is four rectangles with a corner over p, each giving
    // E = L/2 [A/√(1+A²) atan(B/√(1+A²)) + B/√(1+B²) atan(A/√(1+B²))], A = a/h, B = b/h (the form factor of a
    // corner rectangle times π L). Seen from p, its long edges subtend about 167°.
    const double a = 10, b = 1, h = 0.5, radiance = 3;
    const double A = a / h, B = b / h;
    const double corner = radiance / 2 *
                          (A / std::sqrt(1 + A * A) * std::atan(B / std::sqrt(1 + A * A)) +
                           B / std::sqrt(1 + B * B) * std::atan(A / std::sqrt(1 + B * B)));
    const Vec3d p{0.25, -0.5, 2};
    const std::array<Vec3d, 4> corners{p + Vec3d(-a, -b, h), p + Vec3d(a, -b, h), p + Vec3d(a, b, h),
                                       p + Vec3d(-a, b, h)};
    CHECK(polygon_irradiance(corners, p, Vec3d(0, 0, 1), radiance) == Approx(4 * corner).epsilon(1e-9));
}

TEST_CASE("A sphere light fully above the horizon gives pi L (r/d)^2 cos theta",
          "[irradiance][statistical][ex:ch02.sphere_stable][ex:ch04.uniform_hemisphere]") {
    const Vec3 p{0, 0, 0};
    for (const double theta : {0.0, 0.6}) {
        INFO("centre at θ = " << theta);
        const Sphere sphere{Vec3(polar(theta)) * Real(3), 0.9f};
        const double exact = sphere_irradiance(3.0, 0.9, 3.0, std::cos(theta));
        const Estimate brute = brute_irradiance(
            p, 3.0, [&](const Ray& r) { return bool(intersect_sphere(r, sphere, kInfinity)); }, 30);
        CHECK(std::abs(brute.mean - exact) <= 4 * brute.error);
    }
}

TEST_CASE("A coaxial disc gives pi L R^2 / (R^2 + h^2)",
          "[irradiance][statistical][ex:ch04.lambert_polygon][ex:ch04.uniform_hemisphere]") {
    const double radius = 0.7, height = 0.5;
    auto hits_disc = [&](const Ray& r) {
        if (!(r.direction.z > 0)) return false;
        const double t = height / double(r.direction.z);
        const double x = t * double(r.direction.x), y = t * double(r.direction.y);
        return x * x + y * y <= radius * radius;
    };
    const Estimate brute = brute_irradiance(Vec3(0), 1.5, hits_disc, 40);
    CHECK(std::abs(brute.mean - coaxial_disc_irradiance(1.5, radius, height)) <= 4 * brute.error);
    // The polygon formula agrees for a regular 512-gon inscribed in the disc (area ratio 1 − O(1/k²)).
    std::vector<Vec3d> polygon;
    for (int i = 0; i < 512; ++i) {
        const double a = 2 * std::numbers::pi * i / 512;
        polygon.push_back({radius * std::cos(a), radius * std::sin(a), height});
    }
    CHECK(polygon_irradiance(polygon, Vec3d(0), Vec3d(0, 0, 1), 1.5) ==
          Approx(coaxial_disc_irradiance(1.5, radius, height)).epsilon(1e-4));
}

TEST_CASE("A uniform sky gives pi L", "[irradiance][statistical][ex:ch04.uniform_hemisphere]") {
    const Estimate brute = brute_irradiance(
        Vec3(0), 0.8, [](const Ray&) { return true; }, 50);
    CHECK(brute.error > 0);
    CHECK(std::abs(brute.mean - sky_irradiance(0.8)) <= 4 * brute.error);
}

// ---------------------------------------------------------------------------------------------------------
// Light sampling

TEST_CASE("Quad light samples lie on the light, with the pdf of their direction",
          "[lights][ex:ch04.sample_quad_light]") {
    const QuadLight light = make_quad_light({-1, 2, -0.5f}, {0, 0.4f, -1}, {2, 0.3f, 0}, Color(5));
    REQUIRE(light.normal.y < 0);  // faces down, toward p
    const Vec3 p{0.3f, 0, -0.6f};
    Pcg32 rng(60, 0);
    for (int i = 0; i < 1000; ++i) {
        const auto s = sample_quad_light(light, p, rng.next_vec2());
        REQUIRE(s);
        const Vec3 rel = s->point - light.origin;
        REQUIRE(std::abs(glm::dot(rel, light.normal)) < 1e-5f);
        const Real a = glm::dot(glm::cross(rel, light.v), light.normal) / light.area;
        const Real b = glm::dot(glm::cross(light.u, rel), light.normal) / light.area;
        REQUIRE(a >= -1e-5f);
        REQUIRE(a <= 1 + 1e-5f);
        REQUIRE(b >= -1e-5f);
        REQUIRE(b <= 1 + 1e-5f);
        REQUIRE(glm::length(p + s->distance * s->wi - s->point) < 1e-5f);
        REQUIRE(quad_light_pdf(light, p, s->wi) == Approx(s->pdf).epsilon(1e-3));
    }
    // Behind a one-sided light: no sample, and the direction density is 0.
    CHECK_FALSE(sample_quad_light(light, Vec3{0, 5, 0}, Vec2(0.5f)));
    CHECK(quad_light_pdf(light, Vec3{0, 5, 0}, Vec3{0, -1, 0}) == 0);
}

TEST_CASE("Light sampling estimates the exact irradiance of a quad, a triangle and a sphere",
          "[lights][statistical][ex:ch04.cone_solid_angle][ex:ch04.lambert_polygon]"
          "[ex:ch04.sample_quad_light][ex:ch04.uniform_cone][ex:ch04.uniform_triangle]") {
    const Vec3 p{0.2f, 0, 0.1f};
    const Vec3 n{0, 1, 0};
    auto light_estimate = [&](auto sample_one, std::uint64_t seed) {
        Pcg32 rng(seed, 0);
        return estimate(20000, [&] {
            const auto s = sample_one(rng.next_vec2());
            return s ? double(s->radiance.g * std::max(Real(0), glm::dot(s->wi, n)) / s->pdf) : 0.0;
        });
    };
    const QuadLight quad = make_quad_light({-1, 2, -0.5f}, {0, 0.4f, -1}, {2, 0.3f, 0}, Color(5));
    const std::array<Vec3d, 4> corners{Vec3d(quad.origin), Vec3d(quad.origin + quad.u),
                                       Vec3d(quad.origin + quad.u + quad.v), Vec3d(quad.origin + quad.v)};
    const Estimate q = light_estimate([&](Vec2 u) { return sample_quad_light(quad, p, u); }, 61);
    CHECK(std::abs(q.mean - polygon_irradiance(corners, Vec3d(p), Vec3d(n), 5)) <= 4 * q.error);

    const TriangleLight tri = make_triangle_light({-1, 1, 0}, {1, 1.2f, -1}, {0.5f, 1.5f, 1}, Color(2));
    REQUIRE(tri.normal.y < 0);
    const std::array<Vec3d, 3> vertices{Vec3d(tri.p0), Vec3d(tri.p1), Vec3d(tri.p2)};
    const Estimate t = light_estimate([&](Vec2 u) { return sample_triangle_light(tri, p, u); }, 62);
    CHECK(std::abs(t.mean - polygon_irradiance(vertices, Vec3d(p), Vec3d(n), 2)) <= 4 * t.error);

    const SphereLight sphere{{1, 3, 0.5f}, 0.6f, Color(7)};
    const Vec3 to_centre = sphere.center - p;
    const double d = double(glm::length(to_centre));
    const Estimate s = light_estimate([&](Vec2 u) { return sample_sphere_light(sphere, p, u); }, 63);
    CHECK(std::abs(s.mean - sphere_irradiance(7, 0.6, d, double(to_centre.y) / d)) <= 4 * s.error);
}

// ---------------------------------------------------------------------------------------------------------
// Quad lights by solid angle (spherical rectangles, quad_light_strategy.hpp): Ω against closed forms, the
// fallbacks to area sampling where the maths fails, the picker's pdf for MIS, and the irradiance both ways

namespace {

// The exact solid angle of the rectangle [x0, x1] × [y0, y1] lying at distance h below p (p above the origin
// of x, y), by the corner rule: Ω = F(x1, y1) − F(x0, y1) − F(x1, y0) + F(x0, y0), where F(x, y) = arctan(x y
// / (h √(x² + y² + h²))) is the solid angle of [0, x] × [0, y].
double rectangle_solid_angle(double x0, double x1, double y0, double y1, double h) {
    auto F = [h](double x, double y) { return std::atan(x * y / (h * std::sqrt(x * x + y * y + h * h))); };
    return F(x1, y1) - F(x0, y1) - F(x1, y0) + F(x0, y0);
}

// A lamp in the plane z = 0 facing +z (U × V = +z): [x0, x0 + w] × [y0, y0 + h].
QuadLight floor_lamp(Real x0, Real y0, Real w, Real h) {
    return make_quad_light({x0, y0, 0}, {w, 0, 0}, {0, h, 0}, Color(1));
}

}  // namespace

TEST_CASE("The solid angle of a rectangle matches its closed forms, on its axis and oblique",
          "[lights][solid_angle]") {
    // A square of side a seen from distance d on its axis: Ω = 4 arcsin(a² / (a² + 4 d²)) (a cube's face
    // from its centre, a = 2, d = 1: 2π/3).
    for (const auto& [a, d] : {std::pair{2.0, 1.0}, std::pair{1.0, 3.0}, std::pair{0.125, 1.0}}) {
        const auto view =
            SphericalRectangle::seen_from(Vec3(0, 0, Real(d)), Vec3(Real(-a / 2), Real(-a / 2), 0),
                                          Vec3(Real(a), 0, 0), Vec3(0, Real(a), 0));
        REQUIRE(view);
        CHECK(view->solid_angle() == Approx(4 * std::asin(a * a / (a * a + 4 * d * d))).epsilon(1e-12));
    }
    CHECK(4 * std::asin(0.5) == Approx(2 * std::numbers::pi / 3));
    // Rectangles off the axis, down to Ω = 1.2e-4 (just above kMinSphericalSolidAngle): 1e-9 relative.
    const double cases[][5] = {{0.5, 2, -1, 0.25, 1},
                               {-3, -1, 2, 2.5, 0.25},
                               {1, 1.5, 1, 1.75, 4},
                               {-0.25, 0.5, -8, 8, 0.125},
                               {10, 10.5, 0, 0.5, 1}};
    for (const auto& c : cases) {
        const double x0 = c[0], x1 = c[1], y0 = c[2], y1 = c[3], h = c[4];
        const QuadLight lamp = floor_lamp(Real(x0), Real(y0), Real(x1 - x0), Real(y1 - y0));
        const auto view = SphericalRectangle::seen_from(Vec3(0, 0, Real(h)), lamp.origin, lamp.u, lamp.v);
        REQUIRE(view);
        const double exact = rectangle_solid_angle(x0, x1, y0, y1, h);
        INFO("rectangle [" << x0 << ", " << x1 << "] x [" << y0 << ", " << y1 << "] at height " << h);
        CHECK(exact > kMinSphericalSolidAngle);
        CHECK(view->solid_angle() == Approx(exact).epsilon(1e-9));
    }
}

TEST_CASE("Solid-angle sampling hands over to area sampling where its maths fails, and gives nothing behind",
          "[lights][solid_angle][stability][ex:ch04.sample_quad_light]") {
    const QuadLightSampling by = QuadLightSampling::kSolidAngle;
    // Every sample of `lamp` from p drawn by solid angle is area sampling's own sample, field for field.
    auto same_as_area = [&](const QuadLight& lamp, const Vec3& p) {
        Pcg32 rng(7, 0);
        for (int i = 0; i < 100; ++i) {
            const Vec2 u = rng.next_vec2();
            const auto a = sample_quad_light(lamp, p, u), s = sample_quad_light(lamp, p, u, by);
            REQUIRE(a.has_value() == s.has_value());
            if (!a) continue;
            CHECK(s->point == a->point);
            CHECK(s->pdf == a->pdf);
            CHECK(quad_light_pdf(lamp, p, s->wi, by) == quad_light_pdf(lamp, p, s->wi));
        }
    };
    SECTION("a parallelogram has no spherical rectangle") {
        const QuadLight lamp = make_quad_light({0, 0, 0}, {1, 0, 0}, {0.5f, 1, 0}, Color(1));
        CHECK_FALSE(solid_angle_view(lamp, Vec3(0.5f, 0.5f, 1)));
        same_as_area(lamp, Vec3(0.5f, 0.5f, 1));
    }
    SECTION("a tiny, far lamp: Girard's sum of angles near 2 pi cancels, area sampling is exact") {
        // A 1 mm square 100 km away: Ω = A / d² = 1e-16 sr. Its four angles are π/2 each to 1e-8, and
        // γ0 + γ1 + γ2 + γ3 − 2π in double keeps nothing of Ω.
        const QuadLight lamp = floor_lamp(-5e-4f, -5e-4f, 1e-3f, 1e-3f);
        const Vec3 p(0, 0, 1e5f);
        const double exact = double(lamp.area) / (1e5 * 1e5);
        const auto naive = SphericalRectangle::seen_from(p, lamp.origin, lamp.u, lamp.v);
        REQUIRE(naive);
        INFO("naive Omega " << naive->solid_angle() << ", exact " << exact);
        CHECK_FALSE(std::abs(naive->solid_angle() - exact) < 0.5 * exact);
        CHECK_FALSE(solid_angle_view(lamp, p));
        same_as_area(lamp, p);
        const auto s = sample_quad_light(lamp, p, Vec2(0.5f), by);
        REQUIRE(s);
        CHECK(double(s->pdf) == Approx(1 / exact).epsilon(1e-4));
    }
    SECTION("p almost in the lamp's plane: above it, beside it, and by an edge") {
        const QuadLight lamp = floor_lamp(0, 0, 1, 1);
        // Ω above 6.2 sr (over the lamp) or below 1e-4 sr (beside it, and 1e-9 from the plane by an edge,
        // where Girard's sum is already 2e-3 off): area sampling.
        for (const Vec3& p : {Vec3(0.5f, 0.5f, 1e-6f), Vec3(1.5f, 0.5f, 1e-6f), Vec3(0.5f, -1e-3f, 1e-9f)}) {
            INFO("p = " << p.x << ", " << p.y << ", " << p.z);
            CHECK_FALSE(solid_angle_view(lamp, p));
            same_as_area(lamp, p);
        }
        const Vec3 grazing(0.5f, -1e-3f, 1e-9f);
        const double y0 = -double(grazing.y);
        const auto naive = SphericalRectangle::seen_from(grazing, lamp.origin, lamp.u, lamp.v);
        REQUIRE(naive);
        const double grazing_exact = rectangle_solid_angle(-0.5, 0.5, y0, y0 + 1, double(grazing.z));
        CHECK(std::abs(naive->solid_angle() / grazing_exact - 1) > 1e-3);
        // By the edge at 1e-6 (Ω = 2e-3 sr) and 0.01 over the middle (Ω = 6.16 sr) the spherical rectangle
        // serves: its Ω is the closed form's, and every sample is finite, with pdf 1 / Ω.
        for (const Vec3& p : {Vec3(0.5f, -1e-3f, 1e-6f), Vec3(0.5f, 0.5f, 0.01f)}) {
            INFO("p = " << p.x << ", " << p.y << ", " << p.z);
            const auto view = solid_angle_view(lamp, p);
            REQUIRE(view);
            const double x0 = -double(p.x), y = -double(p.y);
            CHECK(view->solid_angle() ==
                  Approx(rectangle_solid_angle(x0, x0 + 1, y, y + 1, double(p.z))).epsilon(1e-6));
            Pcg32 rng(8, 0);
            for (int i = 0; i < 1000; ++i) {
                const auto s = sample_quad_light(lamp, p, rng.next_vec2(), by);
                REQUIRE(s);
                REQUIRE(is_finite(s->point));
                REQUIRE(double(s->pdf) == Approx(1 / view->solid_angle()));
                REQUIRE(quad_light_pdf(lamp, p, s->wi, by) == s->pdf);
            }
        }
    }
    SECTION("behind the one-sided lamp, and in its plane: no sample, density 0") {
        const QuadLight lamp = floor_lamp(0, 0, 1, 1);
        for (const Vec3& p : {Vec3(0.5f, 0.5f, -1), Vec3(0.5f, 0.5f, 0), Vec3(2, 0.5f, 0)}) {
            CHECK_FALSE(solid_angle_view(lamp, p));
            CHECK_FALSE(sample_quad_light(lamp, p, Vec2(0.3f, 0.6f), by));
            CHECK(quad_light_pdf(lamp, p, glm::normalize(Vec3(0.5f, 0.5f, 0) - p + Vec3(0, 0, 1e-3f)), by) ==
                  0);
        }
    }
}

TEST_CASE("The picker's pdf of a hit on a quad is the density its sample drew that direction with, both ways",
          "[lights][solid_angle][mis][ex:ch04.sample_quad_light]") {
    // A rectangle close by, a parallelogram and a far rectangle: the spherical rectangle serves the first and
    // area sampling the others (from p), so the picker's pdf must follow the sampler lamp by lamp.
    const QuadLight quads[] = {make_quad_light({-2, -2, 0.3f}, {0, 4, 0}, {4, 0, 0}, Color(2)),
                               make_quad_light({1, 0, 0.5f}, {0, 1, 0}, {1, 0.5f, 0}, Color(3)),
                               make_quad_light({-5e-4f, 50, 10}, {0, 1e-3f, 0}, {1e-3f, 0, 0}, Color(1e9f))};
    LightSet lights;
    for (int i = 0; i < 3; ++i) {
        lights.lights.push_back(std::make_shared<QuadEmitter>(quads[i]));
        lights.by_hit.push_back(i);
    }
    const Vec3 p(0.1f, 0.2f, 0);
    REQUIRE(solid_angle_view(quads[0], p));
    REQUIRE_FALSE(solid_angle_view(quads[1], p));
    REQUIRE_FALSE(solid_angle_view(quads[2], p));
    for (const QuadLightSampling by : {QuadLightSampling::kArea, QuadLightSampling::kSolidAngle}) {
        const LightPicker picker(lights, by);
        CHECK(picker.quad_lights() == by);
        Pcg32 rng(9, 0);
        int drawn[3] = {0, 0, 0};
        for (int k = 0; k < 3000; ++k) {
            const Real u_pick = rng.next_real();
            const auto s = picker.sample(p, u_pick, rng.next_vec2());
            if (!s) continue;
            const std::size_t i = picker.pick(u_pick);
            ++drawn[i];
            Hit hit;  // what a BSDF sample along s->wi meets
            hit.t = s->distance;
            hit.normal = s->normal;
            hit.light = std::int32_t(i);
            INFO(to_string(by) << ", lamp " << i);
            REQUIRE(picker.pdf(p, s->wi, hit) == Approx(s->pdf).epsilon(1e-4));
            const Real alone = quad_light_pdf(quads[i], p, s->wi, by);
            REQUIRE(picker.pdf(p, s->wi, hit) == Approx(picker.probability(i) * alone).epsilon(1e-3));
        }
        CHECK(drawn[0] > 0);
        CHECK(drawn[1] > 0);
        CHECK(drawn[2] > 0);
    }
}

TEST_CASE(
    "Area and solid-angle sampling estimate the exact irradiance of a rectangle, and near it solid angle is "
    "less noisy",
    "[lights][statistical][solid_angle][ex:ch04.lambert_polygon][ex:ch04.sample_quad_light]") {
    // Lambert's polygon formula gives E exactly; a 4 x 4 lamp 0.3 above a tilted receiver, and a 1 x 2 one 3
    // away.
    const Vec3 p{0.2f, 0, 0.1f};
    const Vec3 n = glm::normalize(Vec3{0.3f, 0, 1});
    for (const QuadLight& lamp : {make_quad_light({-2, -2, 0.4f}, {0, 4, 0}, {4, 0, 0}, Color(5)),
                                  make_quad_light({-1, 0, 3}, {0, 2, 0}, {1, 0, 0}, Color(5))}) {
        const std::array<Vec3d, 4> corners{Vec3d(lamp.origin), Vec3d(lamp.origin + lamp.u),
                                           Vec3d(lamp.origin + lamp.u + lamp.v), Vec3d(lamp.origin + lamp.v)};
        const double exact = polygon_irradiance(corners, Vec3d(p), Vec3d(n), 5);
        Estimate by[2];
        for (const QuadLightSampling strategy : {QuadLightSampling::kArea, QuadLightSampling::kSolidAngle}) {
            Pcg32 rng(64, 0);
            by[int(strategy)] = estimate(20000, [&] {
                const auto s = sample_quad_light(lamp, p, rng.next_vec2(), strategy);
                return s ? double(s->radiance.g * std::max(Real(0), glm::dot(s->wi, n)) / s->pdf) : 0.0;
            });
            INFO(to_string(strategy) << ": " << by[int(strategy)].mean << " +- " << by[int(strategy)].error
                                     << ", exact " << exact);
            CHECK(std::abs(by[int(strategy)].mean - exact) <= 4 * by[int(strategy)].error);
        }
        if (lamp.area > 10) CHECK(by[1].error < 0.5 * by[0].error);
    }
}

TEST_CASE("Sphere light samples lie on the sphere's near side, inside the cone",
          "[lights][ex:ch04.cone_solid_angle][ex:ch04.uniform_cone]") {
    const SphereLight light{{2, 1, -3}, 0.5f, Color(1)};
    const Vec3 p{0, 0, 0};
    const Real d = glm::length(light.center - p);
    const Real cos_max = std::sqrt(1 - (light.radius / d) * (light.radius / d));
    Pcg32 rng(64, 0);
    for (int i = 0; i < 1000; ++i) {
        const auto s = sample_sphere_light(light, p, rng.next_vec2());
        REQUIRE(s);
        REQUIRE(glm::length(s->point - light.center) == Approx(light.radius).epsilon(1e-4));
        REQUIRE(glm::dot(s->point - light.center, p - light.center) >= 0);  // the side facing p
        REQUIRE(glm::dot(s->wi, (light.center - p) / d) >= cos_max - 1e-6f);
        REQUIRE(s->pdf == Approx(sphere_light_pdf(light, p)));
    }
    // From inside the sphere nothing is emitted toward p (it emits outward only).
    CHECK_FALSE(sample_sphere_light(light, light.center + Vec3{0.1f, 0, 0}, Vec2(0.5f)));
    CHECK(sphere_light_pdf(light, light.center) == 0);
}

TEST_CASE("The cone pdf of a sphere of radius 1 at distance 1e4 is finite where the naive 1 - cos gives 0",
          "[lights][stability][ex:ch04.cone_solid_angle][ex:ch04.uniform_cone]") {
    for (const double distance : {1e4, 1e5, 1e6}) {
        INFO("distance " << distance);
        const Real ratio = Real(1 / distance);
        const Real sin2 = ratio * ratio;
        CHECK(one_minus_cos_naive(sin2) ==
              0);  // √(1 − 10⁻⁸) rounds to 1 in float: the cone has no solid angle
        const double exact = 1 / (2 * std::numbers::pi * (1 - std::sqrt(1 - 1 / (distance * distance))));
        const SphereLight light{{0, 0, Real(distance)}, 1, Color(1)};
        const Real pdf = sphere_light_pdf(light, Vec3(0));
        REQUIRE(std::isfinite(pdf));
        // The double reference itself cancels at 1e6; use its series 1 − cos = s²/2 + s⁴/8 there.
        const double s2 = 1 / (distance * distance);
        const double series = 1 / (2 * std::numbers::pi * (s2 / 2 + s2 * s2 / 8));
        CHECK(double(pdf) == Approx(distance <= 1e4 ? exact : series).epsilon(1e-5));
        Pcg32 rng(65, 0);
        for (int i = 0; i < 100; ++i) {
            const auto s = sample_sphere_light(light, Vec3(0), rng.next_vec2());
            REQUIRE(s);
            REQUIRE(std::isfinite(s->pdf));
            REQUIRE(s->pdf == pdf);
            REQUIRE(is_finite(s->point));
            // Float at 10⁶ has a spacing of 1/16: the point is on the sphere to that resolution.
            REQUIRE(std::abs(double(glm::length(s->point - light.center)) - 1) <= 1e-7 * distance * 2 + 1e-6);
        }
    }
}

TEST_CASE("Edge-on, touching and grazing cases give no sample or a finite one, never NaN",
          "[lights][stability][ex:ch04.cone_solid_angle][ex:ch04.cosine_hemisphere][ex:ch04.glossy]"
          "[ex:ch04.lambert][ex:ch04.power_cosine][ex:ch04.power_cosine_pdf][ex:ch04.retroreflective]"
          "[ex:ch04.sample_quad_light][ex:ch04.uniform_cone]") {
    const QuadLight quad = make_quad_light({0, 1, 0}, {0, 0, 1}, {1, 0, 0}, Color(1));  // faces −y
    Pcg32 rng(66, 0);
    // In the light's own plane (edge-on) and at its corner: nothing to sample.
    for (const Vec3& p : {Vec3{-2, 1, 0.5f}, Vec3{0, 1, 0}, Vec3{0.5f, 1, 0.5f}}) {
        for (int i = 0; i < 100; ++i) CHECK_FALSE(sample_quad_light(quad, p, rng.next_vec2()));
    }
    // Just below the plane, far out to the side: finite, tiny contributions.
    for (int i = 0; i < 100; ++i) {
        const auto s = sample_quad_light(quad, Vec3{1e4f, Real(1 - 1e-3), 0.5f}, rng.next_vec2());
        if (s) REQUIRE((std::isfinite(s->pdf) && s->pdf > 0 && is_finite(s->wi)));
    }
    // A point a millionth of a radius above a sphere light: the cone is almost a hemisphere; still finite.
    const SphereLight sphere{{0, 0, 0}, 1, Color(1)};
    for (int i = 0; i < 100; ++i) {
        const auto s = sample_sphere_light(sphere, Vec3{0, Real(1 + 1e-6), 0}, rng.next_vec2());
        REQUIRE(s);
        REQUIRE(std::isfinite(s->pdf));
        REQUIRE(is_finite(s->point));
        REQUIRE(s->distance >= 0);
    }
    // Grazing directions for every BRDF: finite values and pdfs.
    const Vec3 grazing = glm::normalize(Vec3{1, 0, 1e-7f});
    for (const auto& [name, owner] : white_brdfs()) {
        const Bsdf& brdf = *owner;
        INFO(name);
        for (int i = 0; i < 100; ++i) {
            const BsdfSample s = sample(brdf, grazing, kUp, rng.next_vec2());
            REQUIRE((is_finite(s.f) && std::isfinite(s.pdf) && is_finite(s.wi)));
            REQUIRE(is_finite(eval(brdf, grazing, random_unit(rng), kUp)));
        }
    }
}

// ---------------------------------------------------------------------------------------------------------
// Direct lighting

namespace {

// A floor (diffuse plane y = 0) under whatever `lights` adds; a 32×32 camera looking down at it.
struct FloorScene {
    Scene scene;
    FloorScene() {
        scene.camera = CameraDesc{{0, 3, 0.01f}, {0, 0, 0}, {0, 1, 0}, 60};
        scene.materials.push_back(diffuse(Color(0.5f)));
        scene.shapes.push_back(shape(PlaneShape{{0, 0, 0}, {0, 1, 0}}, 0));
    }
    int add_material(const Material& m) {
        scene.materials.push_back(m);
        return int(scene.materials.size()) - 1;
    }
};

RenderResult render_scene(const Scene& scene, DirectOptions options, int size = 32, int spp = 1,
                          int threads = 1, const MaterialHooks& hooks = direct_lighting_materials()) {
    const World world(scene);
    const MaterialTable materials(scene, options.simulated, hooks);
    const DirectLighting shading(world, materials, collect_lights(scene), options);
    const PinholeCamera camera = make_pinhole_camera(scene.camera, size, size);
    const RenderSettings settings{size, size, spp, 3, threads, ProgressStyle::kNone};
    return render_direct(shading, camera, settings, FilmPoints::kStratified);
}

}  // namespace

TEST_CASE("No light in the scene: zero shadow rays, and a black image",
          "[direct][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.plane][ex:ch02.sphere_stable]"
          "[ex:ch04.direct_light]") {
    FloorScene f;
    f.scene.shapes.push_back(shape(SphereShape{{0, 0.5f, 0}, 0.5f}, 0));
    const RenderResult r = render_scene(f.scene, {});
    CHECK(r.rays[RayKind::kCamera] == 32u * 32u);
    CHECK(r.rays[RayKind::kShadow] == 0);
    CHECK(r.image.mean() == 0);
}

TEST_CASE("Lights but only mirrors, or shadows switched off: zero shadow rays",
          "[direct][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.plane][ex:ch03.robust_offset]"
          "[ex:ch03.shadow_ray][ex:ch04.direct_light][ex:ch04.lambert]") {
    FloorScene f;
    f.scene.point_lights.push_back({{0, 2, 0}, Color(10)});
    Material chrome;
    chrome.type = "mirror";
    f.scene.materials[0] = chrome;  // the floor is a mirror: a delta, light samples cannot reach it
    CHECK(render_scene(f.scene, {}).rays[RayKind::kShadow] == 0);
    f.scene.materials[0] = diffuse(Color(0.5f));
    DirectOptions no_shadows;
    no_shadows.simulated = EffectSet::all().without({Effect::kShadows});
    const RenderResult r = render_scene(f.scene, no_shadows);
    CHECK(r.rays[RayKind::kShadow] == 0);
    CHECK(r.image.mean() > 0);
    CHECK(render_scene(f.scene, {}).rays[RayKind::kShadow] == 32u * 32u);  // one per hit for a point light
}

TEST_CASE("A point light gives rho/pi I cos / d^2 and a uniform sky gives rho L, with shadows",
          "[direct][ex:ch01.pixel_sample][ex:ch02.plane][ex:ch02.quad_packet][ex:ch03.robust_offset]"
          "[ex:ch03.shadow_ray][ex:ch04.cosine_hemisphere][ex:ch04.direct_light][ex:ch04.lambert]") {
    FloorScene f;
    f.scene.point_lights.push_back({{0.5f, 2, 0}, Color(8)});
    const World world(f.scene);
    const MaterialTable shading_materials(f.scene, EffectSet::all());
    const DirectLighting shading(world, shading_materials, collect_lights(f.scene), {});
    Pcg32 rng(70, 0);
    RayCounts rays;
    const Ray down{{0, 1, 0}, {0, -1, 0}};
    const Color L = shading.radiance(down, rng, rays);
    const double d2 = 0.25 + 4, cos_theta = 2 / std::sqrt(d2);
    CHECK(double(L.g) == Approx(0.5 / std::numbers::pi * 8 * cos_theta / d2).epsilon(1e-5));
    CHECK(rays[RayKind::kShadow] == 1);

    // Cosine-weighted sky samples make f L cos / pdf = ρ L exactly, for any number of them.
    FloorScene sky;
    sky.scene.environment = EnvironmentLight{Color(2)};
    const World sky_world(sky.scene);
    DirectOptions four;
    four.shadow_samples = 4;
    const MaterialTable sky_shading_materials(sky.scene, EffectSet::all());
    const DirectLighting sky_shading(sky_world, sky_shading_materials, collect_lights(sky.scene), four);
    RayCounts sky_rays;
    CHECK(double(sky_shading.radiance(down, rng, sky_rays).g) == Approx(0.5 * 2).epsilon(1e-5));
    CHECK(sky_rays[RayKind::kShadow] == 4);
    // Under a large blocker the sky is hidden: no light at all.
    sky.scene.shapes.push_back(shape(QuadShape{{-50, 0.5f, -50}, {0, 0, 100}, {100, 0, 0}}, 0));
    const World blocked(sky.scene);
    const MaterialTable blocked_shading_materials(sky.scene, EffectSet::all());
    const DirectLighting blocked_shading(blocked, blocked_shading_materials, collect_lights(sky.scene), four);
    CHECK(blocked_shading.radiance(Ray{{0, 0.25f, 0}, {0, -1, 0}}, rng, sky_rays) == Color(0));
}

TEST_CASE("A distant light gives rho/pi E cos theta on a plane, everywhere, and casts shadows",
          "[direct][lights][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.plane][ex:ch02.quad_packet]"
          "[ex:ch03.robust_offset][ex:ch03.shadow_ray][ex:ch04.direct_light][ex:ch04.lambert]") {
    // Its light travels 60 degrees from straight down, so the floor (albedo 0.5) reads 0.5 E cos 60° / π
    // in every pixel, whether every light is sampled or one is picked by power.
    const std::string lights =
        R"("lights": [{"type": "distant", "direction": [0.8660254, -0.5, 0], "irradiance": [2, 4, 6]}])";
    const std::string floor = R"({"camera": {"from": [0, 3, 0.01], "at": [0, 0, 0], "vfov": 60},
      "materials": {"white": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]}},
      "shapes": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "white"})";
    const Scene scene = parse_scene(floor + "], " + lights + "}", "distant.json");
    REQUIRE(collect_lights(scene).lights.size() == 1);
    for (const LightSelection selection : {LightSelection::kEvery, LightSelection::kPower}) {
        DirectOptions options;
        options.light_selection = selection;
        const RenderResult r = render_scene(scene, options);
        CHECK(r.rays[RayKind::kShadow] == 32u * 32u);
        for (int c = 0; c < 3; ++c) {
            const double expected = 0.5 * 2 * (c + 1) * 0.5 / std::numbers::pi;
            for (const Color& pixel : r.image.pixels())
                REQUIRE(double(pixel[c]) == Approx(expected).epsilon(1e-5));
        }
    }
    // A square roof over the middle of the floor shades the pixels under its shadow, and only them.
    const std::string roof =
        R"(, {"type": "quad", "origin": [-0.5, 0.5, -0.5], "u": [1, 0, 0], "v": [0, 0, 1], "material": "white"})";
    const RenderResult shaded =
        render_scene(parse_scene(floor + roof + "], " + lights + "}", "distant.json"), {});
    int dark = 0;
    for (const Color& pixel : shaded.image.pixels()) dark += pixel == Color(0) ? 1 : 0;
    CHECK(dark > 0);
    CHECK(dark < 32 * 32 / 2);
}

TEST_CASE("A spot light gives rho/pi I falloff cos / d^2: full inside, smooth in the band, nothing outside",
          "[direct][lights][ex:ch01.pixel_sample][ex:ch02.plane][ex:ch03.robust_offset][ex:ch03.shadow_ray]"
          "[ex:ch04.direct_light][ex:ch04.lambert]") {
    // 2 above the floor, pointing straight down: full intensity within 20 degrees of the axis, none
    // beyond 30.
    const Scene scene = parse_scene(R"({"camera": {"from": [0, 3, 0.01], "at": [0, 0, 0]},
      "materials": {"white": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]}},
      "shapes": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "white"}],
      "lights": [{"type": "spot", "position": [0, 2, 0], "at": [0, 0, 0], "intensity": [10, 10, 10],
                  "cone_angle": 30, "cone_delta": 10}]})",
                                    "spot.json");
    const World world(scene);
    const MaterialTable materials(scene, EffectSet::all());
    const DirectLighting shading(world, materials, collect_lights(scene), {});
    Pcg32 rng(71, 0);
    const double cos_end = std::cos(30 * std::numbers::pi / 180),
                 cos_start = std::cos(20 * std::numbers::pi / 180);
    for (const double degrees : {0.0, 8.0, 19.0, 21.0, 25.0, 29.0, 31.0, 40.0}) {
        const double x = 2 * std::tan(degrees * std::numbers::pi / 180);
        const double d2 = x * x + 4, cos_theta = 2 / std::sqrt(d2);
        const double t = std::clamp((cos_theta - cos_end) / (cos_start - cos_end), 0.0, 1.0);
        const double falloff = t * t * (3 - 2 * t);
        RayCounts rays;
        const Color L = shading.radiance(Ray{{Real(x), 1, 0}, {0, -1, 0}}, rng, rays);
        INFO(degrees << " degrees from the axis");
        CHECK(double(L.g) ==
              Approx(0.5 / std::numbers::pi * 10 * falloff * cos_theta / d2).epsilon(1e-5).margin(1e-12));
        CHECK(rays[RayKind::kShadow] == (degrees < 30 ? 1u : 0u));  // none traced outside the cone
    }
}

TEST_CASE("Many lights: picking lights by power costs N shadow rays per hit and agrees with every light",
          "[direct][statistical][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.plane]"
          "[ex:ch02.slab_widening][ex:ch02.sphere_stable][ex:ch02.wide_bvh_traversal]"
          "[ex:ch03.robust_offset][ex:ch03.shadow_ray]"
          "[ex:ch04.cone_solid_angle][ex:ch04.direct_light][ex:ch04.lambert][ex:ch04.uniform_cone]") {
    // 40 small emissive spheres of different brightness above the floor, and one point light.
    FloorScene f;
    f.scene.camera = CameraDesc{{0, 6, 6}, {0, 0, 0}, {0, 1, 0}, 50};
    for (int i = 0; i < 40; ++i) {
        const int lamp = f.add_material(diffuse(Color(0), Color(Real(1 + i % 5))));
        f.scene.shapes.push_back(
            shape(SphereShape{{Real(i % 8) - 3.5f, 1.5f + Real(i / 8) * 0.3f, Real(i / 8) - 2}, 0.1f}, lamp));
    }
    f.scene.point_lights.push_back({{0, 3, 0}, Color(2)});
    DirectOptions every, power, automatic;
    every.light_selection = LightSelection::kEvery;
    power.light_selection = LightSelection::kPower;
    every.shadow_samples = power.shadow_samples = automatic.shadow_samples = 2;
    const RenderResult e = render_scene(f.scene, every, 24, 64, 2);
    const RenderResult p = render_scene(f.scene, power, 24, 64, 2);
    // Every light: 2 shadow rays for each of 40 spheres and one for the point light, per floor hit. Picked:
    // at most 2 per hit, whatever the number of lights.
    const double hits = double(e.rays[RayKind::kCamera]);
    CHECK(double(e.rays[RayKind::kShadow]) > 20 * hits);
    CHECK(double(p.rays[RayKind::kShadow]) <= 2 * hits);
    // The same expected image: the means agree within 2 % (64 samples of 576 pixels each).
    CHECK(p.image.mean() == Approx(e.image.mean()).epsilon(0.02));
    // Beyond 16 lights the automatic choice picks.
    const RenderResult a = render_scene(f.scene, automatic, 24, 64, 2);
    CHECK(a.rays[RayKind::kShadow] == p.rays[RayKind::kShadow]);
    CHECK(a.image.pixels() == p.image.pixels());
}

TEST_CASE("A triangle lamp and a quad lamp light the floor as Lambert's formula says",
          "[direct][statistical][ex:ch01.pixel_sample][ex:ch02.plane][ex:ch02.quad_packet]"
          "[ex:ch02.triangle_watertight][ex:ch03.robust_offset][ex:ch04.direct_light]"
          "[ex:ch04.lambert][ex:ch04.lambert_polygon][ex:ch04.sample_quad_light]"
          "[ex:ch04.uniform_triangle]") {
    // Each lamp alone over the floor (albedo 0.5): the floor's radiance under it is ρ/π E, E from
    // polygon_irradiance. Every kind of light must be summed: a lamp left out gives 0.
    const std::array<Vec3, 3> triangle{Vec3{-0.5f, 1.5f, -0.4f}, Vec3{0.5f, 1.5f, -0.6f},
                                       Vec3{0.6f, 1.5f, 0.5f}};
    const Vec3 quad_origin{-0.5f, 1.5f, -0.5f}, quad_u{1, 0, 0}, quad_v{0, 0, 1};  // u × v = −y
    for (const bool use_triangle : {true, false}) {
        INFO((use_triangle ? "triangle lamp" : "quad lamp"));
        FloorScene f;
        const int lamp = f.add_material(diffuse(Color(0), Color(4)));
        std::vector<Vec3d> corners;
        if (use_triangle) {
            // Wound so that its normal faces the floor.
            f.scene.shapes.push_back(shape(TriangleShape{triangle}, lamp));
            for (const Vec3& v : triangle) corners.push_back(Vec3d(v));
        } else {
            f.scene.shapes.push_back(shape(QuadShape{quad_origin, quad_u, quad_v}, lamp));
            for (const Vec3& v :
                 {quad_origin, quad_origin + quad_u, quad_origin + quad_u + quad_v, quad_origin + quad_v})
                corners.push_back(Vec3d(v));
        }
        const World world(f.scene);
        DirectOptions options;
        options.shadow_samples = 256;
        const MaterialTable materials(f.scene, EffectSet::all());
        const DirectLighting shading(world, materials, collect_lights(f.scene), options);
        Pcg32 rng(72, 0);
        RayCounts rays;
        const Vec3 point{0.1f, 0, 0.05f};
        const Real floor = shading.radiance(Ray{point + Vec3{0, 0.5f, 0}, {0, -1, 0}}, rng, rays).g;
        const double exact =
            0.5 / std::numbers::pi * polygon_irradiance(corners, Vec3d(point), Vec3d(0, 1, 0), 4);
        CHECK(exact > 0.05);
        CHECK(double(floor) == Approx(exact).epsilon(0.03));
    }
}

TEST_CASE("Soft shadows: a blocker under a quad light makes an umbra, a penumbra and full light",
          "[direct][ex:ch01.pixel_sample][ex:ch02.plane][ex:ch02.quad_packet][ex:ch03.robust_offset]"
          "[ex:ch04.direct_light][ex:ch04.lambert][ex:ch04.lambert_polygon]"
          "[ex:ch04.sample_quad_light]") {
    FloorScene f;
    const int lamp = f.add_material(diffuse(Color(0), Color(10)));
    f.scene.shapes.push_back(shape(QuadShape{{-0.5f, 2, -0.5f}, {1, 0, 0}, {0, 0, 1}}, lamp));  // u × v = −y
    f.scene.shapes.push_back(shape(QuadShape{{-0.3f, 1, -0.3f}, {0.6f, 0, 0}, {0, 0, 0.6f}}, 0));  // blocker
    const World world(f.scene);
    DirectOptions options;
    options.shadow_samples = 64;
    const MaterialTable shading_materials(f.scene, EffectSet::all());
    const DirectLighting shading(world, shading_materials, collect_lights(f.scene), options);
    Pcg32 rng(71, 0);
    RayCounts rays;
    auto at = [&](Real x) { return shading.radiance(Ray{{x, 0.5f, 0.001f}, {0, -1, 0}}, rng, rays).g; };
    CHECK(at(0) == 0);  // umbra: every point of the lamp is hidden
    const Real penumbra = at(0.3f);
    const Real lit = at(3);
    CHECK(penumbra > 0);
    // Far out, the blocker hides nothing: the exact value of Lambert's formula, within sampling noise.
    const std::array<Vec3d, 4> corners{Vec3d(-0.5, 2, -0.5), Vec3d(0.5, 2, -0.5), Vec3d(0.5, 2, 0.5),
                                       Vec3d(-0.5, 2, 0.5)};
    const double exact_lit =
        0.5 / std::numbers::pi * polygon_irradiance(corners, Vec3d(3, 0, 0.001), Vec3d(0, 1, 0), 10);
    CHECK(double(lit) == Approx(exact_lit).epsilon(0.05));
    const double exact_centre =
        0.5 / std::numbers::pi * polygon_irradiance(corners, Vec3d(0.3, 0, 0.001), Vec3d(0, 1, 0), 10);
    CHECK(double(penumbra) < exact_centre);
}

namespace {

// Chapter 04's shadow study of ch04_analytic.json at 48×48 (4 and 64 light samples per pixel, each sampler)
// against its exact image. One thread: an exception (a student's unfinished exercise) then reaches the test
// instead of a worker thread.
std::vector<ShadowStudyRow> analytic_shadow_study(const DirectOptions& options,
                                                  const std::vector<LightSampler>& samplers) {
    const Scene scene = load_scene(scene_path("ch04_analytic.json"));
    const MaterialTable materials(scene, EffectSet::all());
    const auto analytic = find_plane_under_quad(scene, materials);
    REQUIRE(analytic);
    const World world(scene);
    const PinholeCamera camera = make_pinhole_camera(scene.camera, 48, 48);
    const Image exact = exact_image(*analytic, world, camera);
    REQUIRE(exact.all_finite());
    REQUIRE(exact.mean() > 0);
    const RenderSettings settings{48, 48, 1, 5, 1, ProgressStyle::kNone};
    return shadow_study(world, materials, collect_lights(scene), options, camera, settings, exact, samplers,
                        {4, 64});
}

}  // namespace

TEST_CASE("The analytic scene converges to its exact image without bias",
          "[direct][statistical][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.plane]"
          "[ex:ch02.quad_packet][ex:ch03.robust_offset][ex:ch04.direct_light][ex:ch04.lambert]"
          "[ex:ch04.lambert_polygon][ex:ch04.sample_quad_light]") {
    const auto rows = analytic_shadow_study({}, {LightSampler::kIndependent, LightSampler::kStratified});
    REQUIRE(rows.size() == 4);
    // Error falls like 1/√N: 16× the samples, about 4× less RMSE.
    CHECK(rows[0].rmse / rows[1].rmse > 3);
    CHECK(rows[0].rmse / rows[1].rmse < 5.3);
    // Unbiased: the mean error is within 4 standard errors of 0 (pixels are independent).
    const double pixels = 48.0 * 48.0;
    for (const ShadowStudyRow& row : rows)
        CHECK(std::abs(row.mean_error) <= 4 * row.rmse / std::sqrt(pixels));
    CHECK(rows[1].shadow_rays == 16 * rows[0].shadow_rays);
    // Stratified light samples: the same rays, less error (the strata even out where the samples fall).
    CHECK(rows[3].shadow_rays == rows[1].shadow_rays);
    CHECK(rows[2].rmse < rows[0].rmse);
    CHECK(rows[3].rmse < rows[1].rmse / 2);
    // A scene that is not a plane under one quad has no exact image.
    Scene scene = load_scene(scene_path("ch04_analytic.json"));
    scene.point_lights.push_back({{0, 1, 0}, Color(1)});
    CHECK_FALSE(find_plane_under_quad(scene, MaterialTable(scene, EffectSet::all())));
}

TEST_CASE("Direct lighting with quads sampled by solid angle converges to the analytic scene's exact image",
          "[direct][statistical][solid_angle][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.plane]"
          "[ex:ch02.quad_packet][ex:ch03.robust_offset][ex:ch04.direct_light][ex:ch04.lambert]"
          "[ex:ch04.lambert_polygon][ex:ch04.sample_quad_light]") {
    DirectOptions options;
    options.quad_lights = QuadLightSampling::kSolidAngle;
    const auto rows = analytic_shadow_study(options, {LightSampler::kIndependent});
    REQUIRE(rows.size() == 2);
    CHECK(rows[0].rmse / rows[1].rmse > 3);
    CHECK(rows[0].rmse / rows[1].rmse < 5.3);
    for (const ShadowStudyRow& row : rows)
        CHECK(std::abs(row.mean_error) <= 4 * row.rmse / std::sqrt(48.0 * 48.0));
}

TEST_CASE(
    "A hit knows its light: Hit::light names the LightSet light the ray hit, for every kind of emitter",
    "[lights][ex:ch02.plane][ex:ch02.quad_packet][ex:ch02.sphere_stable][ex:ch02.triangle_watertight]") {
    // Emitters of every kind among surfaces that emit nothing: a box (6 faces), a triangle, a sphere, a quad,
    // and an emissive plane (no light: infinite area).
    const Scene scene = parse_scene(R"({
      "camera": {"from": [0, 0, 10], "at": [0, 0, 0]},
      "materials": {"lamp": {"type": "diffuse", "albedo": [0, 0, 0], "emission": [2, 2, 2]},
                    "grey": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]}},
      "shapes": [
        {"type": "sphere", "center": [0, -5, 0], "radius": 0.5, "material": "grey"},
        {"type": "box", "min": [-4, -1, -1], "max": [-2, 1, 1], "material": "lamp"},
        {"type": "triangle", "vertices": [[2, -1, 0], [4, -1, 0], [3, 1, 0]], "material": "lamp"},
        {"type": "quad", "origin": [10, 10, 10], "u": [1, 0, 0], "v": [0, 1, 0], "material": "grey"},
        {"type": "sphere", "center": [0, 4, 0], "radius": 1, "material": "lamp"},
        {"type": "quad", "origin": [-1, -8, 0], "u": [2, 0, 0], "v": [0, 2, 0], "material": "lamp"},
        {"type": "plane", "point": [0, 0, -50], "normal": [0, 0, 1], "material": "lamp"}
      ]
    })",
                                    "lights.json");
    const World world(scene);
    const LightSet lights = collect_lights(scene);
    // In the samplers' order: the 7 quads (the 6 box faces and the quad), the triangle, the sphere.
    REQUIRE(kinds_of(lights) == std::vector<std::string_view>{"quad", "quad", "quad", "quad", "quad", "quad",
                                                              "quad", "triangle", "sphere"});
    REQUIRE(lights.by_hit.size() == 9);  // the 6 box faces, the triangle, the sphere, the quad
    Pcg32 rng(90, 0);
    int checked = 0;
    auto aim_at = [&](const Vec3& target, int index) {
        // From far outside the scene's emitters, along a line through the target, so the first hit is on
        // the emitter the target lies on (or on something nearer, which the test then skips).
        const Vec3 from = target + Real(30) * glm::normalize(Vec3(0.3f, 0.2f, 1));
        const auto hit = world.intersect(Ray{from, glm::normalize(target - from)});
        if (!hit || glm::length(hit->point - target) > 1e-3f) return;
        REQUIRE(hit->light >= 0);
        CHECK(lights.by_hit[std::size_t(hit->light)] == index);
        ++checked;
    };
    for (int s = 0; s < 200; ++s) {
        const Vec2 u = rng.next_vec2();
        for (int i = 0; i < 7; ++i) {
            const QuadLight& q = static_cast<const QuadEmitter&>(*lights.lights[std::size_t(i)]).quad();
            aim_at(q.origin + u.x * q.u + u.y * q.v, i);
        }
        const TriangleLight& t = static_cast<const TriangleEmitter&>(*lights.lights[7]).triangle();
        const Real b1 = 1 - std::sqrt(u.x), b2 = u.y * std::sqrt(u.x);
        aim_at((1 - b1 - b2) * t.p0 + b1 * t.p1 + b2 * t.p2, 7);
        const SphereLight& sphere = static_cast<const SphereEmitter&>(*lights.lights[8]).sphere();
        aim_at(sphere.center +
                   sphere.radius * glm::normalize(Vec3(0.3f, 0.2f, 1) + Real(0.5) * random_unit(rng)),
               8);
    }
    CHECK(checked > 500);
    // The emissive plane is no light, and a surface that emits nothing has none.
    const auto plane_hit = world.intersect(Ray{{20, 20, 0}, {0, 0, -1}});
    REQUIRE(plane_hit);
    CHECK(plane_hit->light == -1);
    const auto grey_hit = world.intersect(Ray{{0, -5, 10}, {0, 0, -1}});
    REQUIRE(grey_hit);
    CHECK(grey_hit->light == -1);
}

TEST_CASE(
    "The default scene renders finite, plausible and identical on 1 and 2 threads",
    "[render][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.quad_packet][ex:ch02.slab_widening]"
    "[ex:ch02.sphere_stable]"
    "[ex:ch02.wide_bvh_traversal][ex:ch03.robust_offset][ex:ch04.cone_solid_angle][ex:ch04.direct_light]"
    "[ex:ch04.glossy][ex:ch04.lambert][ex:ch04.retroreflective][ex:ch04.sample_quad_light]"
    "[ex:ch04.uniform_cone]") {
    const Scene scene = load_scene(scene_path("ch04_default.json"));
    const LightSet lights = collect_lights(scene);
    CHECK(kinds_of(lights) == std::vector<std::string_view>{"quad", "sphere"});
    const RenderResult one = render_scene(scene, {}, 40, 2, 1);
    const RenderResult two = render_scene(scene, {}, 40, 2, 2);
    CHECK(one.image.all_finite());
    CHECK(one.image.pixels() == two.image.pixels());
    CHECK(one.image.mean() > 0.05);
    CHECK(one.image.mean() < 0.5);
    CHECK(one.rays[RayKind::kCamera] == 40u * 40u * 2u);
    CHECK(one.rays[RayKind::kShadow] > 0);
    CHECK(one.rays[RayKind::kReflection] == 0);
    CHECK(one.rays[RayKind::kIndirect] == 0);
}

// ---------------------------------------------------------------------------------------------------------
// Textures: the sRGB decode, the image filters and wrap modes, the checkerboard, and the material table's
// one lookup.

TEST_CASE("The sRGB decode is the exact piecewise EOTF, not gamma 2.2", "[texture][srgb]") {
    CHECK(srgb_decode(0) == 0);
    CHECK(srgb_decode(1) == 1);
    // Both pieces meet at the breakpoint c = 0.04045: c / 12.92 = ((c + 0.055) / 1.055)^2.4 there (to 1e-4
    // relative, as the standard rounds its constants).
    const double c = 0.04045;
    CHECK(double(srgb_decode(Real(c))) == Approx(c / 12.92).epsilon(1e-6));
    CHECK(c / 12.92 == Approx(std::pow((c + 0.055) / 1.055, 2.4)).epsilon(1e-4));
    // Above it, the power law in double; below, the line.
    for (double x : {0.01, 0.04, 0.05, 0.2, 0.5, 0.735, 0.99}) {
        const double exact = x <= 0.04045 ? x / 12.92 : std::pow((x + 0.055) / 1.055, 2.4);
        CHECK(double(srgb_decode(Real(x))) == Approx(exact).epsilon(1e-6));
    }
    // Gamma 2.2 is not it: at mid-grey it is 0.2176 against 0.2140, and at the darkest code, 1/255, it is 60
    // times too dark (the EOTF is a line there).
    CHECK(std::pow(0.5, 2.2) == Approx(0.21764).epsilon(1e-4));
    CHECK(double(srgb_decode(0.5f)) == Approx(0.21404).epsilon(1e-4));
    const double darkest = double(srgb_decode(Real(1) / 255)) / std::pow(1.0 / 255, 2.2);
    CHECK(darkest > 59);
    CHECK(darkest < 61);
    // It inverts the encode that writes the PNGs.
    for (int b = 0; b <= 255; ++b) {
        const Real x = Real(b) / 255;
        CHECK(srgb_encode(srgb_decode(x)) == Approx(x).margin(1e-6));
    }
}

namespace {

// 2 × 2 texels, row 0 at the top: red, green / blue, white.
ImageTextureDesc two_by_two(TextureWrap wrap, TextureFilter filter) {
    auto image = std::make_shared<TextureImage>(
        TextureImage{2, 2, {Color{1, 0, 0}, Color{0, 1, 0}, Color{0, 0, 1}, Color{1, 1, 1}}});
    ImageTextureDesc desc;
    desc.image = image;
    desc.wrap = wrap;
    desc.filter = filter;
    return desc;
}

}  // namespace

TEST_CASE("Bilinear filtering of a 2 x 2 image: texel centres, midpoints and the edges wrapped or clamped",
          "[texture][filter]") {
    const ImageTextureDesc repeat = two_by_two(TextureWrap::kRepeat, TextureFilter::kBilinear);
    const ImageTextureDesc clamp = two_by_two(TextureWrap::kClamp, TextureFilter::kBilinear);
    for (const auto* d : {&repeat, &clamp}) {
        // Texel centres (u = ¼, ¾; v up, so the top row is at v = ¾) give the texels themselves.
        CHECK(image_at(*d, {0.25f, 0.75f}) == Color{1, 0, 0});
        CHECK(image_at(*d, {0.75f, 0.75f}) == Color{0, 1, 0});
        CHECK(image_at(*d, {0.25f, 0.25f}) == Color{0, 0, 1});
        CHECK(image_at(*d, {0.75f, 0.25f}) == Color{1, 1, 1});
        // Halfway between two centres: their mean; at the middle, the mean of all four.
        CHECK(image_at(*d, {0.5f, 0.75f}) == Color{0.5f, 0.5f, 0});
        CHECK(image_at(*d, {0.5f, 0.5f}) == Color{0.5f, 0.5f, 0.5f});
        // A quarter of the way: weights ¾ and ¼.
        CHECK(image_at(*d, {0.375f, 0.75f}) == Color{0.75f, 0.25f, 0});
    }
    // At the left edge (u = 0) repeat blends with the right column, clamp stays on the left one.
    CHECK(image_at(repeat, {0, 0.75f}) == Color{0.5f, 0.5f, 0});
    CHECK(image_at(clamp, {0, 0.75f}) == Color{1, 0, 0});
    // Outside [0, 1): repeat takes the fraction (v = −¼ is v = ¾, the top row), clamp the edge.
    CHECK(image_at(repeat, {1.25f, -0.25f}) == Color{1, 0, 0});
    CHECK(image_at(clamp, {1.25f, -0.25f}) == Color{1, 1, 1});
    CHECK(image_at(clamp, {-3, 7}) == Color{1, 0, 0});
    // The scale repeats the image: (su, sv) = (2, 1) puts u = 0.125 on the first texel centre again.
    ImageTextureDesc scaled = repeat;
    scaled.scale = {2, 1};
    CHECK(image_at(scaled, {0.625f, 0.75f}) == Color{1, 0, 0});
    // Far-away coordinates (a plane's, in scene units) stay finite and in range.
    CHECK(is_finite(image_at(repeat, {1e30f, -1e30f})));
    CHECK(is_finite(image_at(repeat, {1e7f + 0.3f, 12345.6f})));
}

TEST_CASE("Nearest filtering and the texel index of each wrap mode", "[texture][filter]") {
    CHECK(wrap_texel(-1, 4, TextureWrap::kRepeat) == 3);
    CHECK(wrap_texel(4, 4, TextureWrap::kRepeat) == 0);
    CHECK(wrap_texel(-9, 4, TextureWrap::kRepeat) == 3);
    CHECK(wrap_texel(-1, 4, TextureWrap::kClamp) == 0);
    CHECK(wrap_texel(4, 4, TextureWrap::kClamp) == 3);
    const ImageTextureDesc nearest = two_by_two(TextureWrap::kRepeat, TextureFilter::kNearest);
    CHECK(image_at(nearest, {0.4f, 0.9f}) == Color{1, 0, 0});
    CHECK(image_at(nearest, {0.6f, 0.9f}) == Color{0, 1, 0});
    CHECK(image_at(nearest, {0.1f, 0.1f}) == Color{0, 0, 1});
    CHECK(image_at(nearest, {0.99f, 0.01f}) == Color{1, 1, 1});
    CHECK(image_at(nearest, {1.1f, 1.9f}) == Color{1, 0, 0});
    const ImageTextureDesc clamped = two_by_two(TextureWrap::kClamp, TextureFilter::kNearest);
    CHECK(image_at(clamped, {1, 0}) == Color{1, 1, 1});  // the edge itself: the last texel, not past it
    CHECK(image_at(clamped, {-0.5f, 2}) == Color{1, 0, 0});
}

TEST_CASE("The checkerboard alternates across every line, zero included", "[texture][checker]") {
    const CheckerDesc d{Color(1), Color(0), 2};
    CHECK(checker_at(d, {0.1f, 0.1f}) == Color(1));
    CHECK(checker_at(d, {0.6f, 0.1f}) == Color(0));
    CHECK(checker_at(d, {0.6f, 0.6f}) == Color(1));
    CHECK(checker_at(d, {-0.1f, 0.1f}) == Color(0));  // ⌊−0.2⌋ = −1: odd, not a doubled square at 0
    CHECK(checker_at(d, {-0.1f, -0.1f}) == Color(1));
    CHECK(checker_at(d, {-5.7f, 3.2f}) == checker_at(d, {-5.7f + 1, 3.2f}));  // period 2 / scale
}

TEST_CASE("The material table evaluates a texture at the hit, and leaves untextured materials as they are",
          "[texture][materials]") {
    Scene scene;
    scene.materials.push_back(diffuse(Color(0.5f)));
    Material checker = diffuse(Color(0.5f));
    checker.textures = {
        {&Material::albedo, TextureDesc{CheckerDesc{Color(0.9f), Color(0.1f), 1}, Color(0.5f)}}};
    scene.materials.push_back(checker);
    Material mirror;
    mirror.type = "mirror";
    mirror.textures = {
        {&Material::reflectance, TextureDesc{CheckerDesc{Color(0.8f), Color(0.2f), 1}, Color(0.5f)}}};
    scene.materials.push_back(mirror);
    const MaterialTable table(scene, EffectSet::all());
    BsdfAtHit at;
    Hit hit;
    hit.material = 0;
    CHECK(&table.bsdf(hit, at) == &table.bsdf(0));
    CHECK(at.empty());
    hit.material = 1;
    hit.uv = {0.5f, 0.5f};
    CHECK(dynamic_cast<const LambertBrdf&>(table.bsdf(hit, at)).albedo == Color(0.9f));
    hit.uv = {1.5f, 0.5f};
    CHECK(dynamic_cast<const LambertBrdf&>(table.bsdf(hit, at)).albedo == Color(0.1f));
    hit.material = 2;
    CHECK(dynamic_cast<const MirrorBrdf&>(table.bsdf(hit, at)).reflectance == Color(0.2f));
    // Without reflection simulated, the mirror is black whatever its texture.
    const MaterialTable no_reflection(scene, EffectSet{Effect::kCameraRays, Effect::kDirect});
    CHECK(is_black(no_reflection.bsdf(hit, at)));
}

TEST_CASE("A checkerboard of one colour renders bit for bit as that colour, and of two it differs",
          "[texture][render][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.plane][ex:ch03.robust_offset]"
          "[ex:ch03.shadow_ray][ex:ch04.direct_light][ex:ch04.lambert]") {
    FloorScene f;
    f.scene.point_lights.push_back({{0, 2, 0}, Color(10)});
    const RenderResult plain = render_scene(f.scene, {});
    f.scene.materials[0].textures = {
        {&Material::albedo, TextureDesc{CheckerDesc{Color(0.5f), Color(0.5f), 4}, Color(0.5f)}}};
    CHECK(render_scene(f.scene, {}).image.pixels() == plain.image.pixels());
    f.scene.materials[0].textures = {
        {&Material::albedo, TextureDesc{CheckerDesc{Color(1), Color(0), 4}, Color(0.5f)}}};
    const RenderResult squares = render_scene(f.scene, {});
    CHECK(squares.image.pixels() != plain.image.pixels());
    CHECK(squares.image.mean() == Approx(plain.image.mean()).epsilon(0.2));
}

TEST_CASE("The textured scene loads its image once, decoded, and renders finite on 1 and 2 threads",
          "[texture][render][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.plane][ex:ch02.quad_packet]"
          "[ex:ch02.sphere_stable][ex:ch03.robust_offset][ex:ch03.shadow_ray][ex:ch04.cosine_hemisphere]"
          "[ex:ch04.direct_light][ex:ch04.lambert][ex:ch04.sample_quad_light]") {
    const Scene scene = load_scene(scene_path("ch04_textured.json"));
    const Scene undecoded = load_scene(scene_path("ch04_textured_undecoded.json"));
    int images = 0;
    for (std::size_t i = 0; i < scene.materials.size(); ++i) {
        const Material& m = scene.materials[i];
        if (m.textures.empty()) continue;
        REQUIRE(m.textures.size() == 1);
        CHECK(m.albedo == m.textures[0].texture.mean);
        if (const auto* image = std::get_if<ImageTextureDesc>(&m.textures[0].texture.pattern)) {
            ++images;
            REQUIRE(image->image);
            CHECK(image->image->width == 64);
            CHECK(image->image->height == 64);
            // Decoded, every texel is darker than its bytes read as they are (0 < c < 1: c^2.4-ish < c).
            const auto& raw =
                std::get<ImageTextureDesc>(undecoded.materials[i].textures[0].texture.pattern).image->texels;
            CHECK(image->image->texels[0].r < raw[0].r);
            CHECK(image->image->texels[0].r == srgb_decode(raw[0].r));
        }
    }
    CHECK(images == 2);
    const RenderResult one = render_scene(scene, {}, 24, 1, 1);
    const RenderResult two = render_scene(scene, {}, 24, 1, 2);
    CHECK(one.image.all_finite());
    CHECK(one.image.pixels() == two.image.pixels());
}

TEST_CASE("A plane's checker alternates square by square as far as 3e7 from the origin, as at the origin",
          "[texture][ex:ch02.plane]") {
    const CheckerDesc checker{Color(1), Color(0), 1};
    // The floor y = 0 through the origin, squares of one unit; its uv are (z, x).
    const Scene scene = parse_scene(R"({"camera": {"from": [0, 1, 0], "at": [0, 0, -1]},
        "materials": {"tiles": {"type": "diffuse", "albedo": {"checker": {"scale": 1}}}},
        "shapes": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "tiles"}]})",
                                    "far.json");
    const World world(scene);
    // From 1 above the point (X, 0, X) (X even: float holds it exactly) to the centres of eight squares in a
    // row: square i has ⌊z⌋ + ⌊x⌋ = 2X + i, even (white) where i is.
    for (const Real far : {Real(0), Real(1e6), Real(3e7)}) {
        for (int i = 0; i < 8; ++i) {
            INFO("X = " << far << ", square " << i);
            const Ray ray{{far, 1, far}, glm::normalize(Vec3(Real(i) + Real(0.5), -1, 0.5))};
            const std::optional<Hit> hit = world.intersect(ray);
            REQUIRE(hit);
            CHECK(checker_at(checker, hit->uv) == (i % 2 == 0 ? Color(1) : Color(0)));
        }
    }
}

namespace {

// A material type that only this file knows: "matte", a Lambert surface of its "albedo" (a colour or a
// texture) through a BSDF class of its own. Registering it is all a new type takes.
class MatteBrdf final : public Bsdf {
  public:
    explicit MatteBrdf(const Color& albedo)
        : Bsdf({.diffuse = true, .black = is_black(albedo)}), lambert_(albedo) {}
    Color eval(const Vec3& wo, const Vec3& wi, const Vec3& n) const override {
        return lambert_.eval(wo, wi, n);
    }
    BsdfSample sample(const Vec3& wo, const Vec3& n, Vec2 u, Real u_lobe) const override {
        return lambert_.sample(wo, n, u, u_lobe);
    }
    Real pdf(const Vec3& wo, const Vec3& wi, const Vec3& n) const override { return lambert_.pdf(wo, wi, n); }

  private:
    LambertBrdf lambert_;
};

void register_matte() {
    if (find_material_kind("matte")) return;
    MaterialKind matte;
    matte.type = "matte";
    matte.keys = {"type", "albedo", "emission"};
    matte.read = [](const scene_reading::Node& node, const std::filesystem::path& folder, Material& m) {
        if (node.has("albedo"))
            scene_reading::read_colour_parameter(node["albedo"], folder, m, &Material::albedo);
    };
    matte.stand_in_albedo = [](const Material& m) { return m.albedo; };
    register_material_kind(matte);
}

MaterialHooks with_matte() {
    MaterialHooks hooks = direct_lighting_materials();
    hooks.models["matte"].bsdf = [](const Material& m, bool, BsdfAtHit& at) -> const Bsdf& {
        return at.emplace<MatteBrdf>(m.albedo);
    };
    return hooks;
}

std::string floor_scene(const std::string& material) {
    return R"({"camera": {"from": [0, 3, 0.01], "at": [0, 0, 0], "vfov": 60},
               "materials": {"floor": )" +
           material + R"(},
               "shapes": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor"}],
               "lights": [{"type": "point", "position": [0, 2, 0], "intensity": [10, 10, 10]}]})";
}

}  // namespace

TEST_CASE(
    "A material type registered in a test file loads from a scene and renders as its BSDF says",
    "[materials][render][ex:ch01.camera_ray][ex:ch01.pixel_sample][ex:ch02.plane][ex:ch03.robust_offset]"
    "[ex:ch03.shadow_ray][ex:ch04.direct_light][ex:ch04.lambert]") {
    register_matte();
    const std::string checker =
        R"({"checker": {"even": [0.9, 0.5, 0.1], "odd": [0.1, 0.2, 0.3], "scale": 4}})";
    const Scene matte = parse_scene(floor_scene(R"({"type": "matte", "albedo": )" + checker + "}"), "m.json");
    const Scene diffuse =
        parse_scene(floor_scene(R"({"type": "diffuse", "albedo": )" + checker + "}"), "d.json");
    REQUIRE(matte.materials[0].type == "matte");
    CHECK_FALSE(kind_of(matte.materials[0]).effect);
    const RenderResult reference = render_scene(diffuse, {});
    const RenderResult rendered = render_scene(matte, {}, 32, 1, 1, with_matte());
    CHECK(rendered.image.pixels() == reference.image.pixels());
    CHECK(reference.image.mean() > 0);
    // Its keys are checked as the course's own types' are; a table without its model stands in for it.
    CHECK_THROWS_WITH(parse_scene(floor_scene(R"({"type": "matte", "roughness": 0.5})"), "m.json"),
                      "m.json: materials.floor.roughness: unknown key for a matte material");
    const MaterialTable without(matte, EffectSet::all());
    REQUIRE(without.notes().size() == 1);
    CHECK(without.notes()[0] ==
          "matte material 'floor': no chapter of this run simulates it; shaded as Lambert (albedo 0.37)");
}
