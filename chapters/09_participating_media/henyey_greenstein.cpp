#include "henyey_greenstein.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "04_direct_lighting/frame.hpp"

namespace rt {

Real henyey_greenstein(Real cos_theta, Real g) {
    const double gd = g, one_minus_cos = 1 - double(cos_theta);
    const double denominator = (1 - gd) * (1 - gd) + 2 * gd * one_minus_cos;  // 1 + g² − 2 g cos θ
    return Real((1 - gd * gd) / (4 * std::numbers::pi * denominator * std::sqrt(denominator)));
}

Real sample_henyey_greenstein_cos(Real g, Real u) {
    // EXERCISE(ch09.hg_sample) § 3. The Henyey–Greenstein phase function
    if (std::abs(g) < Real(1e-3)) return 1 - 2 * u;
    const double gd = g;
    const double s = (1 - gd * gd) / (1 - gd + 2 * gd * double(u));
    const double cos_theta = (1 + gd * gd - s * s) / (2 * gd);
    return Real(std::clamp(cos_theta, -1.0, 1.0));
    // END EXERCISE
}

Real HenyeyGreenstein::eval(const Vec3& wo, const Vec3& wi) const {
    return henyey_greenstein(-glm::dot(wo, wi), g);
}

PhaseSample HenyeyGreenstein::sample(const Vec3& wo, Vec2 u) const {
    const Real cos_theta = sample_henyey_greenstein_cos(g, u.x);
    const Real sin_theta = std::sqrt(std::max(Real(0), (1 - cos_theta) * (1 + cos_theta)));
    const Real phi = 2 * kPi * u.y;
    // θ is measured from the direction of travel, −wo.
    const Vec3 local(sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta);
    const Vec3 wi = glm::normalize(make_frame(-wo).to_world(local));
    const Real p = henyey_greenstein(cos_theta, g);
    return {wi, p, p};
}

}  // namespace rt
