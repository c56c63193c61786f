// What the guide learned at one point, beside what it should have learned: two panels over the equal-area
// square (cos θ across, φ down, as the quadtree stores them), in false colour, each scaled to its maximum.
// Left: the guide's density at the point. Right: the scattered radiance that truly arrives there from each
// direction, estimated by chapter 06's unguided paths from the point (the light an emitter sends straight
// to it left out, as the guide leaves it to next-event estimation).
#pragma once

#include <filesystem>

#include "06_monte_carlo/path_tracer.hpp"
#include "guiding_field.hpp"
#include "rt/core/image.hpp"

namespace rt {

struct GuidePictureRequest {
    std::filesystem::path file;  // empty: no picture
    Vec3 at{0};
    int size = 128;  // each panel's side in pixels
    int paths = 64;  // unguided paths per pixel of the right panel
};

// The picture of `field` at request.at, the right panel traced by `tracer` (on `threads` threads, 0: every
// core), deterministic.
Image guide_picture(const GuidingField& field, const PathTracer& tracer, const GuidePictureRequest& request,
                    int threads);

}  // namespace rt
