#include "homogeneous_medium.hpp"

#include <algorithm>
#include <cmath>

#include "07_bsdf_refraction/dielectric.hpp"

namespace rt {

FreeFlight sample_free_flight(const Color& sigma_t, const Color& sigma_s, Real t_max, int channel, Real u) {
    // EXERCISE(ch09.free_flight) § 2. Free flight
    // Exponentially distributed, through log1p (exact for small u); a channel that does not interact never stops.
    const Real sigma = sigma_t[channel];
    const Real t = sigma > 0 ? -std::log1p(-u) / sigma : kInfinity;
    if (t < t_max) {
        const Color T = beer_lambert(sigma_t, t);
        const Color p = sigma_t * T;  // each channel's density p_k(t) = σ_k e^(−σ_k t)
        return {true, t, sigma_s * T / p[channel], p / p[channel]};
    }
    // Past t_max: each channel's probability of flying that far is its transmittance.
    const Color T = beer_lambert(sigma_t, t_max);
    return {false, t_max, T / T[channel], T / T[channel]};
    // END EXERCISE
}

HomogeneousMedium::HomogeneousMedium(const MediumDesc& desc)
    : sigma_a(desc.sigma_a), sigma_s(desc.sigma_s), sigma_t(desc.sigma_t()), phase_(desc.g) {}

Color HomogeneousMedium::transmittance(Real distance) const {
    // EXERCISE(ch09.transmittance) § 1. The radiative transfer equation
    // Extinction, not absorption alone, takes light out of a ray: scattering sends it elsewhere.
    return beer_lambert(sigma_t, distance);
    // END EXERCISE
}

FreeFlight HomogeneousMedium::sample_free_flight(Real t_max, int channel, Real u) const {
    return rt::sample_free_flight(sigma_t, sigma_s, t_max, channel, u);
}

}  // namespace rt
