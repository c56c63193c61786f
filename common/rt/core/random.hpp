// PCG32 (O'Neill 2014): 64-bit linear congruential state, 32-bit output by xorshift and random rotation.
// Each (pixel, sample, seed) gets its own stream, so an image does not depend on the thread count.
#pragma once

#include <cstdint>

#include "rt/core/math.hpp"

namespace rt {

class Pcg32 {
public:
    Pcg32(std::uint64_t seed, std::uint64_t stream) {
        state_ = 0;
        increment_ = (stream << 1u) | 1u;
        next_uint();
        state_ += seed;
        next_uint();
    }

    // The generator of sample `sample` of pixel `pixel` for the user's `seed`.
    static Pcg32 for_sample(std::uint64_t pixel, std::uint64_t sample, std::uint64_t seed) {
        return Pcg32(mix(seed ^ mix(pixel + 0x9e3779b97f4a7c15ull * (sample + 1))), mix(pixel) ^ sample);
    }

    std::uint32_t next_uint() {
        const std::uint64_t old = state_;
        state_ = old * 6364136223846793005ull + increment_;
        const auto xorshifted = std::uint32_t(((old >> 18u) ^ old) >> 27u);
        const auto rotation = std::uint32_t(old >> 59u);
        return (xorshifted >> rotation) | (xorshifted << ((32u - rotation) & 31u));
    }

    // Uniform in [0, 1): the top bits a float significand holds exactly, scaled so the largest is below 1.
    Real next_real() { return Real(next_uint() >> 8) * Real(0x1.0p-24); }
    Vec2 next_vec2() {
        const Real u = next_real();
        return {u, next_real()};
    }

private:
    // SplitMix64's finaliser: spreads nearby integers over all 64 bits.
    static std::uint64_t mix(std::uint64_t z) {
        z = (z ^ (z >> 30u)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27u)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31u);
    }

    std::uint64_t state_;
    std::uint64_t increment_;
};

}  // namespace rt
