#include "homogeneous_medium.hpp"

#include <algorithm>
#include <cmath>

#include "07_bsdf_refraction/dielectric.hpp"

namespace rt {

FreeFlight sample_free_flight(const Color& sigma_t, const Color& sigma_s, Real t_max, Real u_channel, Real u,
                              ChannelPdf weighting) {
    // EXERCISE(ch09.free_flight)
    const int c = std::min(2, int(u_channel * 3));
    // t = −ln(1 − u) / σ_c: exponentially distributed; a channel that does not interact never stops.
    const Real t = sigma_t[c] > 0 ? -std::log1p(-u) / sigma_t[c] : kInfinity;
    if (t < t_max) {
        const Color T = beer_lambert(sigma_t, t);
        const Color p = sigma_t * T;  // each channel's density p_k(t) = σ_k e^(−σ_k t)
        const Real pdf = weighting == ChannelPdf::kAverage ? (p.r + p.g + p.b) / 3 : p[c];
        return {true, t, sigma_s * T / pdf};
    }
    // Past t_max: each channel's probability of flying that far is its transmittance.
    const Color T = beer_lambert(sigma_t, t_max);
    const Real probability = weighting == ChannelPdf::kAverage ? (T.r + T.g + T.b) / 3 : T[c];
    return {false, t_max, T / probability};
    // END EXERCISE
}

HomogeneousMedium::HomogeneousMedium(const MediumDesc& desc)
    : sigma_a(desc.sigma_a), sigma_s(desc.sigma_s), sigma_t(desc.sigma_t()), phase_(desc.g) {}

Color HomogeneousMedium::transmittance(Real distance) const {
    // EXERCISE(ch09.transmittance)
    // Extinction, not absorption alone, takes light out of a ray: scattering sends it elsewhere.
    return beer_lambert(sigma_t, distance);
    // END EXERCISE
}

FreeFlight HomogeneousMedium::sample_free_flight(Real t_max, Pcg32& rng) const {
    const Real u_channel = rng.next_real();
    return rt::sample_free_flight(sigma_t, sigma_s, t_max, u_channel, rng.next_real());
}

}  // namespace rt
