// Where the path loop's random numbers come from: a sample's stream of uniform numbers in [0, 1), each draw
// the next dimensions of the sample. The loop draws through this one interface (next_real, next_vec2) from
//   independent: chapter 01's Pcg32 stream of the (pixel, sample, seed), the camera ray through a uniform
//                point of the pixel;
//   stratified:  the same, the camera ray through the sample's stratum of the pixel;
//   sobol:       the Owen-scrambled Sobol sequence of the pixel (owen_sobol.hpp), point `sample` of it, each
//                draw a pair of its dimensions (the default).
// Every stream is a pure function of (pixel, sample, seed), so an image is the same for any thread count.
#pragma once

#include "owen_sobol.hpp"
#include "rt/core/enum_names.hpp"
#include "rt/core/random.hpp"

namespace rt {

enum class PointSet { kIndependent, kStratified, kSobol };
inline constexpr PointSet kAllPointSets[] = {PointSet::kIndependent, PointSet::kStratified, PointSet::kSobol};

constexpr auto names_of(PointSet) {
    return enum_names<PointSet>("--sampler", {{PointSet::kIndependent, "independent"},
                                              {PointSet::kStratified, "stratified"},
                                              {PointSet::kSobol, "sobol"}});
}

// A handle on a sample's stream (cheap to copy: copies draw from the same stream).
class SampleStream {
  public:
    // Implicit: whatever has a Pcg32 draws from it.
    SampleStream(Pcg32& rng) : rng_(&rng) {}  // NOLINT(google-explicit-constructor)
    SampleStream(OwenSobolStream& sobol, Pcg32& rng) : sobol_(&sobol), rng_(&rng) {}

    Real next_real() { return sobol_ ? sobol_->next_real() : rng_->next_real(); }
    Vec2 next_vec2() {
        if (sobol_) return sobol_->next_vec2();
        const Real u = next_real();
        return {u, next_real()};
    }

  private:
    OwenSobolStream* sobol_ = nullptr;
    Pcg32* rng_;
};

}  // namespace rt
