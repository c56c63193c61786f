// One ulp up or down: what std::nextafter(v, ±∞) returns, without its call into the maths library. Floats of
// one sign are ordered like their bit patterns read as integers, so the next float away from zero is the
// pattern plus one and the next toward zero the pattern minus one (PBRT 4 §6.8.1). From ±0 the step is the
// smallest subnormal; an infinity in the step's direction, and NaN, stay as they are.
#pragma once

#include <bit>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "rt/core/math.hpp"

namespace rt {

using RealBits = std::conditional_t<sizeof(Real) == 4, std::uint32_t, std::uint64_t>;

// The smallest Real above v.
inline Real next_float_up(Real v) {
    if (!(v < kInfinity)) return v;
    if (v == 0) return std::numeric_limits<Real>::denorm_min();
    const RealBits bits = std::bit_cast<RealBits>(v);
    return std::bit_cast<Real>(v > 0 ? bits + 1 : bits - 1);
}

// The largest Real below v.
inline Real next_float_down(Real v) {
    if (!(v > -kInfinity)) return v;
    if (v == 0) return -std::numeric_limits<Real>::denorm_min();
    const RealBits bits = std::bit_cast<RealBits>(v);
    return std::bit_cast<Real>(v > 0 ? bits - 1 : bits + 1);
}

}  // namespace rt
