#include "denoiser.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>


namespace rt {

namespace {

std::string describe(Denoiser denoiser, const DenoiseSettings& s) {
    if (denoiser == Denoiser::kNone) return "none";
    char text[200];
    const EdgeStopping& e = denoiser == Denoiser::kBilateral ? s.bilateral.edges : s.atrous.edges;
    if (denoiser == Denoiser::kAtrous) {
        std::snprintf(text, sizeof text, "atrous (%d levels", s.atrous.levels);
    } else {
        std::snprintf(text, sizeof text, "bilateral (sigma_s %g px", double(s.bilateral.spatial));
    }
    std::string out = text;
    std::snprintf(text, sizeof text, ", sigma colour %g, normal %g, depth %g, albedo %g)", double(e.colour),
                  double(e.normal), double(e.depth), double(e.albedo));
    return out + text;
}

}  // namespace

std::vector<std::string> denoise_notes(Denoiser denoiser, const DenoiseSettings& settings, const Denoised& denoised,
                                       double render_seconds) {
    char time[160];
    std::snprintf(time, sizeof time, "filter time %.3f s (the render %.3f s: %.1f%% more)", denoised.seconds,
                  render_seconds, 100.0 * denoised.seconds / std::max(render_seconds, 1e-9));
    return {"denoiser " + describe(denoiser, settings), time};
}

Denoised denoise(const FeatureBuffers& buffers, Denoiser denoiser, const DenoiseSettings& settings) {
    const auto start = std::chrono::steady_clock::now();
    Denoised out;
    switch (denoiser) {
        case Denoiser::kNone:
            out.image = buffers.colour;
            break;
        case Denoiser::kBilateral:
            out.image = bilateral_filter(buffers, settings.bilateral, settings.threads);
            break;
        case Denoiser::kAtrous:
            out.image = atrous_filter(buffers, settings.atrous, settings.threads);
            break;
    }
    out.seconds = denoiser == Denoiser::kNone
                      ? 0
                      : std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

}  // namespace rt
