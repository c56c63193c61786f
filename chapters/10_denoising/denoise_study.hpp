// What a denoiser buys, measured fairly against a converged reference (chapter 07's cached reference, an
// independent seed):
//   1. each denoiser at the run's spp: relative MSE, RMSE, SSIM, signed mean error, render and filter time;
//   2. equal error: the spp plain path tracing needs to reach each denoiser's relative MSE (renders at
//   doubling
//      spp, interpolated log-log between the two that bracket it) and its time, against the render plus the
//      filter: how many times sooner the denoised image gets there;
//   3. the bias: over independent runs (seeds), MSE = bias² + variance per pixel, so bias² ≈ MSE − variance
//      (relative: each term over r² + 0.01, as the relative MSE); a path tracer's is 0 up to the noise of
//      the estimate and of the reference, a filter's is what it smooths away that was not noise;
//   4. failure regions of the Cornell box, measured on their own: the caustic under the glass sphere, the
//      image refracted in it, the lamp's edge, and fine geometry (the rods of ch10_default.json);
//   5. with `sweeps`, each filter's parameters one at a time.
#pragma once

#include <string>

#include "06_monte_carlo/path_tracer.hpp"
#include "denoiser.hpp"
#include "rt/core/image.hpp"
#include "rt/core/scene.hpp"
#include "rt/render/render_loop.hpp"

namespace rt {

struct StudyOptions {
    int reference_spp = 4096;
    std::string cache = ".";  // folder of the reference PFM (chapter 07's name for it)
    int runs = 4;             // independent runs for the bias
    std::string crops;        // folder for PNG strips of the regions (reference | noisy | bilateral | atrous)
    bool sweeps = false;
};

// A region of the image in fractions of its width and height, named.
struct StudyRegion {
    const char* name;
    double x0, y0, x1, y1;
};

// The failure regions of the Cornell box of cornell.json and ch10_default.json (the camera of both).
const std::vector<StudyRegion>& cornell_regions();
PixelRect pixels_of(const StudyRegion& region, int width, int height);

// Image `image` cut to `rect`.
Image crop(const Image& image, const PixelRect& rect);

// Probes --crops, then prints the study (stdout).
void run_denoise_study(const Scene& scene, const RenderSettings& settings, const PathOptions& options,
                       const DenoiseSettings& denoise_settings, const StudyOptions& study);

}  // namespace rt
