// How much light a smooth dielectric interface reflects. η = η_t / η_i is the ratio of the index on the far
// side (where a transmitted ray goes) to the index on the near side (where wo is); cos θ_i = n · wo.
// Entering versus leaving: cos θ_i < 0 means wo is on the other side of n, so the sides swap: the functions
// use −cos θ_i and 1 / η (the normal and the ratio flip together).
// Snell's law gives the transmitted angle: sin θ_t = sin θ_i / η; when sin θ_t >= 1 nothing is transmitted
// (total internal reflection, possible only for η < 1, i.e. leaving the denser medium).
//   exact (Fresnel, unpolarized light):  r_perp = −sin(θ_i − θ_t) / sin(θ_i + θ_t),
//                                        r_par  = tan(θ_i − θ_t) / tan(θ_i + θ_t),
//                                        R = (r_par² + r_perp²) / 2,  T = 1 − R; the code uses their form in
//                                        cos θ_i, cos θ_t and η (the lesson derives it).
//   conductor (complex index η + i k, unpolarized; pbrt-v4's FrComplex): the same exact formula with the
//                                        complex index: sin² θ_t = sin² θ_i / (η + i k)², cos θ_t its complex
//                                        square root, R = (|r_par|² + |r_perp|²) / 2. Nothing is transmitted
//                                        (a metal absorbs what enters within nanometres): T is absorbed.
//                                        At k = 0 it is the dielectric's R (total internal reflection gives
//                                        |r| = 1); at normal incidence R = ((η − 1)² + k²) / ((η + 1)² + k²);
//                                        at grazing incidence R → 1.
//   Schlick (1994):                      R ≈ R0 + (1 − R0) (1 − cos θ)^5,  R0 = ((η − 1) / (η + 1))²,
//                                        θ the angle on the less dense side (θ_t when η < 1).
#pragma once

#include "rt/core/math.hpp"

namespace rt {

// cos² θ_t at or below this counts as total internal reflection: a transmitted ray that close to the tangent
// plane is only rounding away from it (exactly at the critical angle sin θ_t = 1), carries T → 0, and would
// skim the surface. Four float ulps of 1.
inline constexpr Real kTirCos2 = 4 * std::numeric_limits<Real>::epsilon();

// cos² θ_t = 1 − (1 − cos² θ_i) / η² (Snell), clamped at 0; ≤ kTirCos2 means total internal reflection.
// For cos_i >= 0 (wo on n's side); cos_i above 1 by rounding counts as 1.
Real cos2_transmitted(Real cos_i, Real eta);

// Turns (cos θ_i, η) to wo's side: for cos θ_i < 0, (−cos θ_i, 1 / η).
void face_incident_side(Real& cos_i, Real& eta);

// The exact Fresnel reflectance above; 1 under total internal reflection.
Real fresnel_dielectric(Real cos_i, Real eta);

// The conductor's exact reflectance above, for cos_i in [0, 1] (wo on n's side: a metal has no inside), of
// one colour channel's η >= 0 and k >= 0, not both 0.
Real fresnel_conductor(Real cos_i, Real eta, Real k);
// The same for the three channels.
Color fresnel_conductor(Real cos_i, const Color& eta, const Color& k);

// Schlick's approximation above; 1 under total internal reflection.
Real fresnel_schlick(Real cos_i, Real eta);

}  // namespace rt
