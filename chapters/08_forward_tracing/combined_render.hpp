// Paths from both ends, each kind of path counted by the tracer that finds it best. Chapter 06's path
// tracer finds a caustic (light from a lamp through glass onto the floor) only when a BSDF sample at the
// floor happens to pass through the glass and hit the lamp: rarely, and then at full weight, a firefly. Light
// sampling cannot help: its shadow rays stop at the glass. A light path finds the same caustic every time it
// passes through the glass, and its connection to the camera lands where the caustic is. So the image is
// split by the kind of path, read from the camera (D a non-delta vertex, S a delta one):
//
//   I = I_paths + I_light,
//   I_light: the paths E D{1..K} S … (1 to K non-delta vertices, then glass or a mirror: the caustics the
//            camera sees with nothing delta in between), found by light paths (LightPathSet::kCaustics),
//            R of them per camera sample;
//   I_paths: every other path, found by chapter 06's loop, which ends a path where it would enter one of
//            the light tracer's (camera_caustic_cut.hpp, with the same K).
//
// Each path is counted by exactly one of the two, at its full weight, so the sum is unbiased for any R and
// K (a partition of path space; multiple importance sampling would weigh both, at the cost of each tracer
// evaluating the other's density). The path tracer keeps what the camera sees through glass or a mirror
// (E S …): no connection to a pinhole passes a delta vertex.
#pragma once

#include "06_monte_carlo/path_tracer.hpp"
#include "light_tracer.hpp"
#include "rt/core/scene.hpp"
#include "rt/render/render_loop.hpp"

namespace rt {

struct CombinedOptions {
    PathOptions paths;                 // its `simulated` is set from the render's effects
    // R: light paths per camera sample (R × spp × width × height of them). 0.5 reached a relative MSE of 1e-3
    // on the glass box sooner than 1 (ch08_time_to_error, chapter 08's lesson).
    Real light_paths_per_sample = 0.5;
    int caustic_bounces = kSafetyDepthCap;  // K: the light paths' share is E D{1..K} S …; the default, every
                                            // path that meets glass or a mirror after diffuse bounces alone
};

struct CombinedResult {
    RenderResult render;   // the sum: its image I_paths + I_light, its rays and seconds both tracers'
    RenderResult paths;    // I_paths alone
    SplatResult caustics;  // I_light alone
    bool split = false;    // false: the scene was rendered by paths alone (other light, or a medium)
};

// Renders `scene` both ways (chapter 07's materials: radiance for the camera's paths, importance for the
// light's) and adds the two images.
CombinedResult render_combined(const Scene& scene, const EffectSet& simulated, const RenderSettings& settings,
                               const CombinedOptions& options);

}  // namespace rt
