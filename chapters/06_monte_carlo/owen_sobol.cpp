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

namespace {

// Sobol's second dimension read and written bit-reversed: reverse_bits(sobol_bits(reverse_bits(r), 1)). The
// generator is linear over bits, so this too is four byte lookups.
constexpr std::array<std::array<std::uint32_t, 256>, 4> reversed_second_dimension_bytes() {
    constexpr std::array<std::uint32_t, 32> v = second_dimension_directions();
    std::array<std::array<std::uint32_t, 256>, 4> t{};
    for (std::size_t b = 0; b < 4; ++b) {
        for (std::size_t x = 0; x < 256; ++x) {
            for (std::size_t k = 0; k < 8; ++k) {
                if (!(x >> k & 1u)) continue;
                // Bit 8b + k of r is bit 31 − 8b − k of the index: it adds direction v_{32−8b−k}, reversed.
                std::uint32_t d = v[31 - (8 * b + k)], reversed = 0;
                for (std::size_t bit = 0; bit < 32; ++bit) reversed |= (d >> bit & 1u) << (31 - bit);
                t[b][x] ^= reversed;
            }
        }
    }
    return t;
}
constexpr std::array<std::array<std::uint32_t, 256>, 4> kReversedSecondDimensionBytes =
    reversed_second_dimension_bytes();

// The scrambles of one pair of dimensions: of the index's shuffle, of x and of y (the pair's own Pcg32
// stream of the sequence's seed).
struct PairSeeds {
    std::uint32_t shuffle, x, y;
};
PairSeeds pair_seeds(std::uint64_t seed, std::uint32_t pair) {
    Pcg32 seeds(seed, pair);
    const std::uint32_t shuffle = seeds.next_uint();
    const std::uint32_t x = seeds.next_uint();
    return {shuffle, x, seeds.next_uint()};
}

// The top 24 bits of a 32-bit fraction as a Real in [0, 1), as Pcg32::next_real: at most 1 − 2^-24.
Real to_unit(std::uint32_t bits) {
    return Real(bits >> 8u) * Real(0x1.0p-24);
}

// The shuffled index, bit-reversed: reverse_bits(nested_uniform_scramble(index, seed)), one reversal fewer.
std::uint32_t reversed_shuffle(std::uint32_t index, std::uint32_t seed) {
    return laine_karras_permutation(reverse_bits(index), seed);
}

// Coordinate x of the pair from the reversed shuffle r = reverse(shuffled). By the definitions,
//   x = nested_uniform_scramble(sobol_bits(shuffled, 0), s) = reverse(LK(reverse(reverse(shuffled)), s)):
// the scramble undoes the van der Corput reversal, and x = reverse(LK(reverse(r), s)).
std::uint32_t scrambled_x(std::uint32_t r, std::uint32_t seed) {
    return reverse_bits(laine_karras_permutation(reverse_bits(r), seed));
}
// Coordinate y: nested_uniform_scramble(sobol_bits(shuffled, 1), s) = reverse(LK(reversed second dimension
// of r, s)).
std::uint32_t scrambled_y(std::uint32_t r, std::uint32_t seed) {
    const auto& t = kReversedSecondDimensionBytes;
    const std::uint32_t reversed_y =
        t[0][r & 0xffu] ^ t[1][r >> 8u & 0xffu] ^ t[2][r >> 16u & 0xffu] ^ t[3][r >> 24u];
    return reverse_bits(laine_karras_permutation(reversed_y, seed));
}

}  // namespace

Vec2 owen_sobol_pair(std::uint32_t index, std::uint32_t pair, std::uint64_t seed) {
    // The pair of dimensions (2j, 2j+1) is a (0, 2)-sequence of its own: its own shuffle of the index (an
    // Owen scramble of it, which maps each aligned block of 2^m indices onto one), its own digit scrambles.
    const PairSeeds s = pair_seeds(seed, pair);
    const std::uint32_t r = reversed_shuffle(index, s.shuffle);
    return {to_unit(scrambled_x(r, s.x)), to_unit(scrambled_y(r, s.y))};
}

Real owen_sobol(std::uint32_t index, std::uint32_t dimension, std::uint64_t seed) {
    const PairSeeds s = pair_seeds(seed, dimension / 2);
    const std::uint32_t r = reversed_shuffle(index, s.shuffle);
    return to_unit(dimension % 2 == 0 ? scrambled_x(r, s.x) : scrambled_y(r, s.y));
}

OwenSobolStream::OwenSobolStream(std::uint64_t pixel, std::uint32_t sample, std::uint64_t seed)
    : index_(sample) {
    // The pixel's own sequence: 64 bits of its generator (the generator of its sample 0).
    Pcg32 rng = Pcg32::for_sample(pixel, 0, seed);
    seed_ = std::uint64_t(rng.next_uint()) << 32u;
    seed_ |= rng.next_uint();
}

}  // namespace rt
