// PCG32 (O'Neill 2014), the course's generator (common/rt/core/random.hpp), line for line: the same 64-bit state,
// the same stream per (pixel, sample, seed), the same 32-bit outputs. A GPU's integer units are 32 bits wide;
// GL_ARB_gpu_shader_int64 gives uint64_t, which each multiply turns into a few 32-bit instructions.

struct Pcg32 {
    uint64_t state;
    uint64_t increment;
};

uint pcg_next_uint(inout Pcg32 rng) {
    // EXERCISE(ch11.pcg32) § The same estimator
    const uint64_t old = rng.state;
    rng.state = old * 6364136223846793005UL + rng.increment;
    const uint xorshifted = uint(((old >> 18u) ^ old) >> 27u);
    const uint rotation = uint(old >> 59u);
    return (xorshifted >> rotation) | (xorshifted << ((32u - rotation) & 31u));
    // END EXERCISE
}

Pcg32 pcg_new(uint64_t seed, uint64_t stream) {
    Pcg32 rng = Pcg32(0UL, (stream << 1u) | 1UL);
    pcg_next_uint(rng);
    rng.state += seed;
    pcg_next_uint(rng);
    return rng;
}

// SplitMix64's finaliser: spreads nearby integers over all 64 bits.
uint64_t pcg_mix(uint64_t z) {
    z = (z ^ (z >> 30u)) * 0xbf58476d1ce4e5b9UL;
    z = (z ^ (z >> 27u)) * 0x94d049bb133111ebUL;
    return z ^ (z >> 31u);
}

// The generator of sample `s` of pixel `pixel` for the user's `seed`: Pcg32::for_sample.
Pcg32 pcg_for_sample(uint64_t pixel, uint64_t s, uint64_t seed) {
    return pcg_new(pcg_mix(seed ^ pcg_mix(pixel + 0x9e3779b97f4a7c15UL * (s + 1UL))), pcg_mix(pixel) ^ s);
}

// Uniform in [0, 1), every value exact in float: Pcg32::next_real's bits.
float pcg_next_real(inout Pcg32 rng) {
    // EXERCISE(ch11.next_real) § The same estimator
    return float(pcg_next_uint(rng) >> 8u) * (1.0 / 16777216.0);
    // END EXERCISE
}

vec2 pcg_next_vec2(inout Pcg32 rng) {
    const float u = pcg_next_real(rng);
    return vec2(u, pcg_next_real(rng));
}
