// What chapter 07 adds to chapter 04's material table: with refraction simulated, a dielectric is glass — the
// smooth dielectric of dielectric.hpp, or, when its "roughness" is above 0, the rough one of
// rough_dielectric.hpp — and absorbing glass is filled with Beer–Lambert's medium (a scattering "medium",
// which chapter 09 simulates, with the absorption of its σ_a + σ_s). With reflection simulated, a conductor
// is a metal (conductor.hpp): its exact complex Fresnel, smooth or GGX-rough; and a coateddiffuse is a Lambert
// base under a clear coat (coated_diffuse.hpp).
#pragma once

#include "04_direct_lighting/material_table.hpp"
#include "dielectric.hpp"

namespace rt {

// Chapter 04's hooks and these three types; `transport` is what the paths that read the table carry (its
// dielectrics' BTDF).
MaterialHooks refraction_materials(Transport transport = Transport::kRadiance);

}  // namespace rt
