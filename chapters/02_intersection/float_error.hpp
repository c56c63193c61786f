// Bounds on floating-point rounding error (Higham; PBRT 4 §6.8). Each float operation returns the exact
// result times (1 + δ) with |δ| <= u = 2^-24 (half an ulp of 1); n operations in a row stay within (1 ± γ_n),
// γ_n = n u / (1 − n u). A hit point carries such a bound, so chapter 03 can spawn rays just clear of it.
#pragma once

#include <limits>

#include "rt/core/math.hpp"

namespace rt {

// The unit roundoff u of Real: half the distance from 1 to the next Real.
inline constexpr Real kUnitRoundoff = std::numeric_limits<Real>::epsilon() / 2;

// γ_n = n u / (1 − n u): the relative error bound of n rounded operations.
constexpr Real gamma_bound(int n) {
    return Real(n) * kUnitRoundoff / (1 - Real(n) * kUnitRoundoff);
}

}  // namespace rt
