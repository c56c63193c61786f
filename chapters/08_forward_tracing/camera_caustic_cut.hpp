// The path tracer's half of the partition of path space (combined_render.hpp): a PathObserver that ends
// chapter 06's path where it would enter the light tracer's share, E D{1..K} S … (1 to K non-delta vertices
// from the camera, then a delta one: glass, a mirror). The path ends at that delta vertex; what follows is
// the light tracer's (LightPathSet::kCaustics with the same K). Only for scenes without media, whose lights
// are all sampled.
#pragma once

#include "06_monte_carlo/path_observer.hpp"

namespace rt {

class CameraCausticCut final : public PathObserver {
  public:
    explicit CameraCausticCut(int max_bounces) : max_bounces_(max_bounces) {}

    bool reached(const Hit& /*hit*/, const BsdfFlags& flags, int bounces) override {
        if (!flags.delta) return true;
        if (clear_so_far_ && bounces >= 1 && bounces <= max_bounces_) return false;
        clear_so_far_ = false;
        return true;
    }

  private:
    int max_bounces_;           // K
    bool clear_so_far_ = true;  // no delta vertex yet: the path so far is E D*
};

}  // namespace rt
