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

// A map that is linear over bits, a byte at a time: t[b][x] = ⊕ of columns[8b + k] over the bits k set in
// byte x, so that the image of a 32-bit word costs four lookups rather than a loop over its 32 bits.
using ByteTables = std::array<std::array<std::uint32_t, 256>, 4>;
constexpr ByteTables byte_tables(const std::array<std::uint32_t, 32>& columns) {
    ByteTables t{};
    for (std::size_t b = 0; b < 4; ++b) {
        for (std::size_t x = 0; x < 256; ++x) {
            for (std::size_t k = 0; k < 8; ++k) {
                if (x >> k & 1u) t[b][x] ^= columns[8 * b + k];
            }
        }
    }
    return t;
}
constexpr std::uint32_t apply(const ByteTables& t, std::uint32_t x) {
    return t[0][x & 0xffu] ^ t[1][x >> 8u & 0xffu] ^ t[2][x >> 16u & 0xffu] ^ t[3][x >> 24u];
}

// Sobol's second dimension: bit k of the index adds direction v_{k+1}.
constexpr ByteTables kSecondDimensionBytes = byte_tables(second_dimension_directions());

// The same read and written bit-reversed, reverse_bits(sobol_bits(reverse_bits(r), 1)): bit i of r is bit
// 31 − i of the index, and adds v_{32−i}, reversed.
constexpr std::array<std::uint32_t, 32> reversed_second_dimension_columns() {
    const std::array<std::uint32_t, 32> v = second_dimension_directions();
    std::array<std::uint32_t, 32> columns{};
    for (std::size_t i = 0; i < 32; ++i) columns[i] = reverse_bits(v[31 - i]);
    return columns;
}
constexpr ByteTables kReversedSecondDimensionBytes = byte_tables(reversed_second_dimension_columns());

}  // namespace

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
    return apply(kSecondDimensionBytes, index);
}

namespace {

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

// Coordinate y of the pair from the reversed shuffle r: nested_uniform_scramble(sobol_bits(shuffled, 1), s)
// = reverse(LK(reversed second dimension of r, s)), the two reversals between them left out.
std::uint32_t scrambled_y(std::uint32_t r, std::uint32_t seed) {
    return reverse_bits(laine_karras_permutation(apply(kReversedSecondDimensionBytes, r), seed));
}

}  // namespace

Vec2 owen_sobol_pair(std::uint32_t index, std::uint32_t pair, std::uint64_t seed) {
    // The pair of dimensions (2j, 2j+1) is a (0, 2)-sequence of its own: its own shuffle of the index (an
    // Owen scramble of it, which maps each aligned block of 2^m indices onto one), its own digit scrambles.
    const PairSeeds s = pair_seeds(seed, pair);
    const std::uint32_t r = reversed_shuffle(index, s.shuffle);
    // Coordinate x: nested_uniform_scramble(sobol_bits(shuffled, 0), s), and sobol_bits(shuffled, 0) = r.
    return {to_unit(nested_uniform_scramble(r, s.x)), to_unit(scrambled_y(r, s.y))};
}

Real owen_sobol(std::uint32_t index, std::uint32_t dimension, std::uint64_t seed) {
    const PairSeeds s = pair_seeds(seed, dimension / 2);
    const std::uint32_t r = reversed_shuffle(index, s.shuffle);
    return to_unit(dimension % 2 == 0 ? nested_uniform_scramble(r, s.x) : scrambled_y(r, s.y));
}

OwenSobolStream::OwenSobolStream(std::uint64_t pixel, std::uint32_t sample, std::uint64_t seed)
    : index_(sample) {
    // The pixel's own sequence: 64 bits of its generator (the generator of its sample 0).
    Pcg32 rng = Pcg32::for_sample(pixel, 0, seed);
    seed_ = std::uint64_t(rng.next_uint()) << 32u;
    seed_ |= rng.next_uint();
}

}  // namespace rt
