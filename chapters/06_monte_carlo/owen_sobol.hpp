// Low-discrepancy samples: an Owen-scrambled Sobol sequence, after B. Burley, "Practical Hash-based Owen
// Scrambling", Journal of Computer Graphics Techniques 9(4), 2020 (its nested_uniform_scramble and the hash
// of S. Laine and T. Karras, "Stratified Sampling for Stochastic Transparency", 2011, written here from the
// paper's description).
//
// The first two Sobol dimensions form a (0, 2)-sequence in base 2: every aligned block of 2^m consecutive
// points puts exactly one point in each elementary interval [a/2^k, (a+1)/2^k) × [b/2^(m−k), (b+1)/2^(m−k)).
//   dimension 0: the van der Corput sequence, x₀(i) = the bits of i mirrored about the binary point;
//   dimension 1: Sobol's second, generator matrix from the primitive polynomial x + 1 (all m_k = 1), so its
//                direction numbers are v₁ = 1/2, v_k = v_{k−1} ⊕ (v_{k−1} / 2) (Pascal's triangle mod 2).
// Owen scrambling flips each digit of a point by a random function of the digits before it: the points stay a
// (0, 2)-sequence and each one is uniform on [0, 1)², so the estimate is unbiased, and for a smooth integrand
// its error falls like N^(−3/4)·√log N rather than N^(−1/2). Burley's hash does it in a few multiplications:
// reverse the bits, apply a hash in which each bit depends only on the bits below it, reverse back.
// Further dimensions are padded (Burley §4): the pair of dimensions (2j, 2j+1) takes the same two Sobol
// dimensions, with its own scrambles and its own Owen-scrambled shuffle of the sample index, so the pairs are
// independent of each other while each stays a (0, 2)-sequence over a pixel's samples.
#pragma once

#include <cstdint>

#include "rt/core/math.hpp"

namespace rt {

// Each bit of x mirrored: bit b goes to bit 31 − b.
constexpr std::uint32_t reverse_bits(std::uint32_t x) {
    x = ((x >> 1u) & 0x55555555u) | ((x & 0x55555555u) << 1u);
    x = ((x >> 2u) & 0x33333333u) | ((x & 0x33333333u) << 2u);
    x = ((x >> 4u) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4u);
    x = ((x >> 8u) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8u);
    return (x >> 16u) | (x << 16u);
}
// Laine and Karras's hash: each output bit depends on the input bits at and below it only.
std::uint32_t laine_karras_permutation(std::uint32_t x, std::uint32_t seed);
// An Owen scramble of a 32-bit fraction (bit 31 the first digit): reverse, permute, reverse.
std::uint32_t nested_uniform_scramble(std::uint32_t x, std::uint32_t seed);
// The unscrambled Sobol point's coordinate in `dimension` (0 or 1) as a 32-bit fraction.
std::uint32_t sobol_bits(std::uint32_t index, int dimension);

// Dimensions 2j and 2j + 1 of point `index` of the Owen-scrambled, padded Sobol sequence of `seed`, in
// [0, 1)²: a pure function of its arguments.
Vec2 owen_sobol_pair(std::uint32_t index, std::uint32_t pair, std::uint64_t seed);
// Coordinate `dimension` (any) of the same point.
Real owen_sobol(std::uint32_t index, std::uint32_t dimension, std::uint64_t seed);

// A stream of sample `index` of a pixel's sequence: each draw is the next dimension, with the interface of
// Pcg32 (next_real, next_vec2), so that code that draws numbers can draw from either.
class OwenSobolStream {
  public:
    // The stream of sample `sample` of pixel `pixel` for the user's `seed`: the pixel's samples share one
    // scrambled sequence, of which this is point `sample`.
    OwenSobolStream(std::uint64_t pixel, std::uint32_t sample, std::uint64_t seed);

    // Each draw takes a pair of dimensions of its own, so that a 2D draw (a direction, a point on a light)
    // is a (0, 2)-sequence over the pixel's samples; a 1D draw keeps the pair's first coordinate.
    Real next_real() { return owen_sobol(index_, 2 * pair_++, seed_); }
    Vec2 next_vec2() { return owen_sobol_pair(index_, pair_++, seed_); }

  private:
    std::uint32_t index_;
    std::uint32_t pair_ = 0;
    std::uint64_t seed_;
};

}  // namespace rt
