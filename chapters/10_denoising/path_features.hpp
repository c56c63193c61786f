// What the camera ray's path meets at its first vertex that is not a delta bounce, having followed mirrors
// and glass the way it goes on: the features a denoiser is guided by, recorded by a PathObserver as the path
// loop runs (the path and its random numbers are the same with or without it). Left as it is (zeros, not
// recorded) by a path that leaves the scene first.
#pragma once

#include "06_monte_carlo/path_observer.hpp"

namespace rt {

class PathFeatures final : public PathObserver {
  public:
    Color albedo{0};  // the bounce's weight there, f |cos θ_i| / pdf, times the delta chain's β before it:
                      // an estimate of the surface's albedo ρ(wo) as seen through the chain (0 on a light)
    Vec3 normal{0};   // the shading normal there, on the side the path came from
    Real depth = 0;   // the path's length from the camera to there, through the chain
    bool recorded = false;

    bool reached(const Hit& hit, const BsdfFlags& flags, int /*bounces*/) override {
        length_ += hit.t;
        if (!recorded && !flags.delta) {
            normal = hit.shading_normal;
            depth = length_;
            recorded = recording_ = true;
        }
        return true;
    }
    void sampled(const Color& beta, const BsdfSample& sample, Real cos_i) override {
        if (recording_) albedo = beta * sample.f * (cos_i / sample.pdf);
        recording_ = false;
    }

  private:
    Real length_ = 0;         // of the path so far
    bool recording_ = false;  // the vertex just reached is the recorded one: its bounce is the albedo
};

}  // namespace rt
