// What reverse tracing saves, measured (`--forward-study`):
//  1. On chapter 06's Cornell box: the fraction of traced light paths that ever reach the camera, through a
//     lens aperture of radius R (it falls like R²) and by connecting every vertex to the pinhole.
//  2. Time to the same RMSE: chapter 06's path tracer (MIS, and BRDF sampling alone) at 4, 16, 64 spp
//     against its converged reference (chapter 06's cached PFM), and the time the light tracer needs to
//     reach each of those RMSEs (interpolated on its own log RMSE–log time curve).
//  3. Where forward tracing wins and loses, on ch08_default.json (the glass sphere focuses the lamp on the
//     floor) and ch08_mirror.json (a mirror panel throws it onto the back wall): the RMSE of the light tracer
//     and of chapter 07's path tracer on the pixels of the caustic, of the mirror or glass, and the rest,
//     against chapter 07's converged image (cached as PFM).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "02_intersection/world.hpp"
#include "04_direct_lighting/render_scene.hpp"
#include "06_monte_carlo/path_tracer.hpp"
#include "light_tracer.hpp"
#include "rt/core/effect_set.hpp"
#include "rt/core/image.hpp"

namespace rt {

struct StudyOptions {
    int size = 100;                           // the image is size × size
    std::uint64_t fraction_paths = 1u << 20;  // light paths behind each fraction
    int reference_spp = 8192;                 // chapter 06's Cornell box (chapter 06 caches it at this spp)
    int glass_reference_spp = 4096;           // the mirror and glass scenes (chapter 07's tracer is slower)
    std::string cache = ".";  // where converged references are read (chapter 06's files) or written
    std::string csv;          // the time-to-RMSE table, when not empty
    int threads = 0;
    std::uint64_t seed = 1;
};

// A scene and what both tracers need to render it, every effect simulated: its World, lights and material
// table for radiance paths (prepared), the same materials for light paths (importance), and a width × height
// pinhole camera.
struct StudyScene {
    Scene scene;
    RenderScene prepared;
    MaterialTable importance;
    PinholeCamera camera;
    StudyScene(Scene s, int width, int height);
};

// RMSE over the pixels where mask is true (all channels).
double masked_rmse(const Image& image, const Image& reference, const std::vector<std::uint8_t>& mask);

// The time at which a curve of (seconds, RMSE) points, falling with time, reaches `rmse`: linear in
// log–log between the two points around it; above its first point's RMSE and past its last point,
// extrapolated from that point with RMSE ∝ t^(−1/2).
double time_to_rmse(const std::vector<double>& seconds, const std::vector<double>& rmse, double target);

// Runs the three measurements and prints them.
void run_forward_study(const StudyOptions& options);

}  // namespace rt
