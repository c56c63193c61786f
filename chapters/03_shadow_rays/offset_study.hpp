// What each ray offset costs and what it gets wrong, measured on one scene at several scales. For each scale
// s (scale_scene) and each method, the picture is rendered and timed as usual; then every camera sample's
// shadow rays are traced again and judged against ExactVisibility (double precision, own shape left out):
//  - a self-hit is a shadow ray whose nearest hit is the very surface it left;
//  - an acne pixel has a shadow ray that is blocked where the light is in fact visible (dark specks);
//  - a leak pixel has a shadow ray that is free where the light is in fact blocked (light leaking through a
//    thin gap or a contact: the ray started beyond the occluder).
// The cost of the offset itself is timed apart too: offset_origin for the shadow rays of every pixel centre.
// The methods take turns round after round and each time is a median, so the load of a shared machine falls
// on all of them alike.
#pragma once

#include <cstdint>
#include <vector>

#include "ray_offset.hpp"
#include "rt/core/scene.hpp"
#include "rt/render/render_loop.hpp"

namespace rt {

struct OffsetStudyRow {
    Real scale = 1;
    RayOffset offset;
    double seconds = 0;    // the render alone, as the executable renders it (median of 3)
    double offset_ns = 0;  // offset_origin alone, ns per call on one thread (median of 7)
    std::uint64_t shadow_rays = 0;
    std::uint64_t self_hits = 0;
    std::uint64_t acne_pixels = 0;
    std::uint64_t leak_pixels = 0;
    double mean = 0;  // the image's mean radiance (the same for every scale when nothing goes wrong)
};

// One row per (scale, method), scales in the outer loop.
std::vector<OffsetStudyRow> offset_study(const Scene& scene, const std::vector<Real>& scales,
                                         const std::vector<RayOffset>& methods,
                                         const RenderSettings& settings);

}  // namespace rt
