#include "owen_sobol.hpp"

#include <array>

#include "rt/core/random.hpp"

namespace rt {
namespace {

// Direction numbers of Sobol's second dimension: v₁ = 2^31, v_k = v_{k−1} ⊕ (v_{k−1} >> 1).
constexpr std::array<std::uint32_t, 32> second_dimension_directions() {
    std::array<std::uint32_t, 32> v{};
    v[0] = 1u << 31u;
    for (std::size_t k = 1; k < 32; ++k) v[k] = v[k - 1] ^ (v[k - 1] >> 1u);
    return v;
}
// The same, a byte at a time: kSecondDimensionBytes[b][x] = ⊕ of v_{8b+k+1} over the bits k set in byte x, so
// that a point costs four lookups rather than a loop over 32 bits (a shuffled index has all 32).
constexpr std::array<std::array<std::uint32_t, 256>, 4> second_dimension_bytes() {
    constexpr std::array<std::uint32_t, 32> v = second_dimension_directions();
    std::array<std::array<std::uint32_t, 256>, 4> t{};
    for (std::size_t b = 0; b < 4; ++b) {
        for (std::size_t x = 0; x < 256; ++x) {
            for (std::size_t k = 0; k < 8; ++k) {
                if (x >> k & 1u) t[b][x] ^= v[8 * b + k];
            }
        }
    }
    return t;
}
constexpr std::array<std::array<std::uint32_t, 256>, 4> kSecondDimensionBytes = second_dimension_bytes();

}  // namespace

std::uint32_t reverse_bits(std::uint32_t x) {
    x = ((x >> 1u) & 0x55555555u) | ((x & 0x55555555u) << 1u);
    x = ((x >> 2u) & 0x33333333u) | ((x & 0x33333333u) << 2u);
    x = ((x >> 4u) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4u);
    x = ((x >> 8u) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8u);
    return (x >> 16u) | (x << 16u);
}

std::uint32_t laine_karras_permutation(std::uint32_t x, std::uint32_t seed) {
    // Burley 2020's constants. Adding the seed carries only upwards, and x ⊕= x·c with an even c changes bit
    // k by bits below k only: a bijection in which each bit depends on the bits at and below it.
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

std::uint32_t nested_uniform_scramble(std::uint32_t x, std::uint32_t seed) {
    // Reversed, the first digit of the fraction is the lowest bit, on which every other bit may depend.
    return reverse_bits(laine_karras_permutation(reverse_bits(x), seed));
}

std::uint32_t sobol_bits(std::uint32_t index, int dimension) {
    if (dimension == 0) return reverse_bits(index);
    return kSecondDimensionBytes[0][index & 0xffu] ^ kSecondDimensionBytes[1][index >> 8u & 0xffu] ^
           kSecondDimensionBytes[2][index >> 16u & 0xffu] ^ kSecondDimensionBytes[3][index >> 24u];
}

Vec2 owen_sobol_pair(std::uint32_t index, std::uint32_t pair, std::uint64_t seed) {
    // The pair of dimensions (2j, 2j+1) is a (0, 2)-sequence of its own: its own shuffle of the index (an
    // Owen scramble of it, which maps each aligned block of 2^m indices onto one), its own digit scrambles.
    Pcg32 seeds(seed, pair);
    const std::uint32_t shuffled = nested_uniform_scramble(index, seeds.next_uint());
    const std::uint32_t x = nested_uniform_scramble(sobol_bits(shuffled, 0), seeds.next_uint());
    const std::uint32_t y = nested_uniform_scramble(sobol_bits(shuffled, 1), seeds.next_uint());
    // The top 24 bits, as Pcg32::next_real: the largest value is 1 − 2^-24.
    return {Real(x >> 8u) * Real(0x1.0p-24), Real(y >> 8u) * Real(0x1.0p-24)};
}

Real owen_sobol(std::uint32_t index, std::uint32_t dimension, std::uint64_t seed) {
    const Vec2 p = owen_sobol_pair(index, dimension / 2, seed);
    return dimension % 2 == 0 ? p.x : p.y;
}

OwenSobolStream::OwenSobolStream(std::uint64_t pixel, std::uint32_t sample, std::uint64_t seed)
    : index_(sample) {
    // The pixel's own sequence: 64 bits of its generator (the generator of its sample 0).
    Pcg32 rng = Pcg32::for_sample(pixel, 0, seed);
    seed_ = std::uint64_t(rng.next_uint()) << 32u;
    seed_ |= rng.next_uint();
}

}  // namespace rt
