#include "irradiance_estimators.hpp"

#include <chrono>
#include <cmath>

#include "01_ray_generation/pixel_sampling.hpp"
#include "04_direct_lighting/area_light_sampling.hpp"
#include "04_direct_lighting/frame.hpp"
#include "04_direct_lighting/irradiance.hpp"
#include "04_direct_lighting/sampling.hpp"
#include "04_direct_lighting/sphere_light_sampling.hpp"
#include "mis.hpp"
#include "owen_sobol.hpp"
#include "rt/core/random.hpp"
#include "warp_pdfs.hpp"

namespace rt {
namespace {

const Vec3 kOrigin{0, 0, 0};

// L(wi): the radiance arriving at p = 0 along wi, and the light-sampling density of wi.
struct Arrival {
    Real radiance;
    Real light_pdf;
};

Arrival arrival(const IrradianceCase& c, const Vec3& wi) {
    if (c.quad) {
        const QuadLight& q = *c.quad;
        const Real pdf = quad_light_pdf(q, kOrigin, wi);
        return {pdf > 0 ? q.radiance.g : Real(0), pdf};
    }
    if (c.sphere) {
        const SphereLight& s = *c.sphere;
        const Real d = glm::length(s.center);
        const Real ratio = s.radius / d;
        const Vec3 local = make_frame(s.center / d).to_local(wi);
        const Real pdf = uniform_cone_pdf(local, one_minus_cos_stable(ratio * ratio));
        return {pdf > 0 ? s.radiance.g : Real(0), pdf};
    }
    if (c.environment) return {c.environment->radiance.g, cosine_hemisphere_pdf(wi.z)};
    return {0, 0};
}

// A light sample from p = 0: the direction and its density (0 when it carries no light).
struct Drawn {
    Vec3 wi;
    Real pdf;
    Real radiance;
};

Drawn light_sample(const IrradianceCase& c, Vec2 u) {
    std::optional<LightSample> s;
    if (c.quad)
        s = sample_quad_light(*c.quad, kOrigin, u);
    else if (c.sphere)
        s = sample_sphere_light(*c.sphere, kOrigin, u);
    else if (c.environment) {
        const Vec3 wi = sample_cosine_hemisphere(u);
        return {wi, cosine_hemisphere_pdf(wi.z), c.environment->radiance.g};
    }
    if (!s) return {{0, 0, 1}, 0, 0};
    return {s->wi, s->pdf, s->radiance.g};
}

// One sample's estimate of E with `strategy` from the points u and v of [0, 1)².
double one_estimate(const IrradianceCase& c, SamplingStrategy strategy, Vec2 u, Vec2 v) {
    switch (strategy) {
        case SamplingStrategy::kUniform: {
            const Vec3 wi = sample_uniform_hemisphere(u);
            return double(arrival(c, wi).radiance * wi.z / kUniformHemispherePdf);
        }
        case SamplingStrategy::kCosine:
        case SamplingStrategy::kBrdf: {
            const Vec3 wi = sample_cosine_hemisphere(u);
            const Real pdf = cosine_hemisphere_pdf(wi.z);
            return pdf > 0 ? double(arrival(c, wi).radiance * wi.z / pdf) : 0.0;
        }
        case SamplingStrategy::kLight: {
            const Drawn d = light_sample(c, u);
            return d.pdf > 0 && d.wi.z > 0 ? double(d.radiance * d.wi.z / d.pdf) : 0.0;
        }
        case SamplingStrategy::kMis: {
            double sum = 0;
            const Drawn d = light_sample(c, u);
            if (d.pdf > 0 && d.wi.z > 0) {
                sum += double(power_heuristic(d.pdf, cosine_hemisphere_pdf(d.wi.z)) * d.radiance * d.wi.z /
                              d.pdf);
            }
            const Vec3 wi = sample_cosine_hemisphere(v);
            const Real pdf = cosine_hemisphere_pdf(wi.z);
            const Arrival a = arrival(c, wi);
            if (pdf > 0 && a.radiance > 0) {
                sum += double(power_heuristic(pdf, a.light_pdf) * a.radiance * wi.z / pdf);
            }
            return sum;
        }
    }
    return 0;
}

}  // namespace

std::vector<IrradianceCase> irradiance_cases() {
    std::vector<IrradianceCase> cases;
    {
        // A 1×1 square at height 1, its near edge over p's x = 0.2, facing down (u × v = −z).
        IrradianceCase c;
        c.name = "quad";
        const Vec3 origin{0.2f, -0.5f, 1}, u{0, 1, 0}, v{1, 0, 0};
        c.quad = make_quad_light(origin, u, v, Color(1));
        const std::vector<Vec3d> polygon{Vec3d(origin), Vec3d(origin + u), Vec3d(origin + u + v),
                                         Vec3d(origin + v)};
        c.exact = polygon_irradiance(polygon, Vec3d(0), Vec3d(0, 0, 1), 1.0);
        cases.push_back(c);
    }
    {
        IrradianceCase c;
        c.name = "sphere";
        const Vec3 center{1, 0, 2};
        c.sphere = SphereLight{center, 0.5f, Color(1)};
        const double d = glm::length(Vec3d(center));
        c.exact = sphere_irradiance(1.0, 0.5, d, double(center.z) / d);
        cases.push_back(c);
    }
    {
        IrradianceCase c;
        c.name = "sky";
        c.environment = EnvironmentLight{Color(1)};
        c.exact = sky_irradiance(1.0);
        cases.push_back(c);
    }
    return cases;
}

IrradianceEstimate estimate_irradiance(const IrradianceCase& c, SamplingStrategy strategy, int samples,
                                       std::uint64_t seed, PointSet points) {
    Pcg32 rng(seed, 3);
    const auto start = std::chrono::steady_clock::now();
    double sum = 0, sum2 = 0;
    const PixelSampler sampler =
        points == PointSet::kStratified ? PixelSampler::kStratified : PixelSampler::kUniform;
    for (int j = 0; j < samples; ++j) {
        Vec2 u, v;
        if (points == PointSet::kSobol) {
            // Point j of the sequence of this seed: dimensions 0, 1 for u and 2, 3 for v.
            OwenSobolStream stream(0, std::uint32_t(j), seed);
            u = stream.next_vec2();
            v = stream.next_vec2();
        } else {
            // Chapter 01's pixel sampler in pixel (0, 0) spreads the points over the unit square.
            u = pixel_sample_point(sampler, 0, 0, j, samples, rng.next_vec2());
            v = pixel_sample_point(sampler, 0, 0, j, samples, rng.next_vec2());
        }
        const double x = one_estimate(c, strategy, u, v);
        sum += x;
        sum2 += x * x;
    }
    IrradianceEstimate e;
    e.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double n = double(samples);
    e.mean = sum / n;
    e.variance = samples > 1 ? std::max(0.0, (sum2 - sum * sum / n) / (n - 1)) : 0.0;
    e.standard_error = std::sqrt(e.variance / n);
    return e;
}

}  // namespace rt
