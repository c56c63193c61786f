// Uniformly distributed unit vectors for the tests of chapters 02–05 (before chapter 06 teaches sphere
// sampling): z uniform in [−1, 1] and φ uniform in [0, 2π) give a uniform point on the sphere (Archimedes).
#pragma once

#include <algorithm>
#include <cmath>

#include "rt/core/math.hpp"
#include "rt/core/random.hpp"

namespace rt {

inline Vec3 random_unit(Pcg32& rng) {
    const Real z = 1 - 2 * rng.next_real();
    const Real r = std::sqrt(std::max(Real(0), 1 - z * z));
    const Real phi = 2 * kPi * rng.next_real();
    return {r * std::cos(phi), r * std::sin(phi), z};
}

}  // namespace rt
