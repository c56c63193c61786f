#include "fresnel.hpp"

#include <algorithm>
#include <cmath>
#include <complex>

namespace rt {

Real cos2_transmitted(Real cos_i, Real eta) {
    const Real c = std::clamp(cos_i, Real(0), Real(1));
    const Real sin2_t = (1 - c * c) / (eta * eta);
    return std::max(Real(0), 1 - sin2_t);
}

void face_incident_side(Real& cos_i, Real& eta) {
    if (cos_i < 0) {
        cos_i = -cos_i;
        eta = 1 / eta;
    }
    cos_i = std::min(cos_i, Real(1));
}

Real fresnel_dielectric(Real cos_i, Real eta) {
    // EXERCISE(ch07.fresnel_exact) § Fresnel: how much reflects
    face_incident_side(cos_i, eta);
    const Real cos2_t = cos2_transmitted(cos_i, eta);
    if (cos2_t <= kTirCos2) return 1;
    const Real ci = cos_i;
    const Real ct = std::sqrt(cos2_t);
    const Real r_par = (eta * ci - ct) / (eta * ci + ct);
    const Real r_perp = (ci - eta * ct) / (ci + eta * ct);
    return std::min(Real(1), (r_par * r_par + r_perp * r_perp) / 2);
    // END EXERCISE
}

Real fresnel_conductor(Real cos_i, Real eta, Real k) {
    const Real ci = std::clamp(cos_i, Real(0), Real(1));
    // EXERCISE(ch07.fresnel_conductor) § Rough metals
    using Complex = std::complex<Real>;
    if (ci == 0) return 1;  // grazing: both amplitudes are −1 (the formula's 0 / 0 when η + i k = 1)
    const Complex n(eta, k);
    const Complex sin2_t = (1 - ci * ci) / (n * n);
    const Complex ct = std::sqrt(Complex(1) - sin2_t);  // the principal root: Re ≥ 0, a wave that decays
    const Complex r_par = (n * ci - ct) / (n * ci + ct);
    const Complex r_perp = (ci - n * ct) / (ci + n * ct);
    return std::min(Real(1), (std::norm(r_par) + std::norm(r_perp)) / 2);
    // END EXERCISE
}

Color fresnel_conductor(Real cos_i, const Color& eta, const Color& k) {
    return {fresnel_conductor(cos_i, eta.r, k.r), fresnel_conductor(cos_i, eta.g, k.g),
            fresnel_conductor(cos_i, eta.b, k.b)};
}

Real fresnel_schlick(Real cos_i, Real eta) {
    // EXERCISE(ch07.fresnel_schlick) § Fresnel: how much reflects
    face_incident_side(cos_i, eta);
    const Real cos2_t = cos2_transmitted(cos_i, eta);
    if (cos2_t <= kTirCos2) return 1;
    const Real r0 = ((eta - 1) / (eta + 1)) * ((eta - 1) / (eta + 1));
    // The angle on the less dense side: θ_i entering a denser medium, θ_t leaving it.
    const Real c = eta >= 1 ? cos_i : std::sqrt(cos2_t);
    const Real m = 1 - c;
    const Real m2 = m * m;
    return r0 + (1 - r0) * m2 * m2 * m;
    // END EXERCISE
}

}  // namespace rt
