#include "denoiser.hpp"

#include <chrono>

#include "rt/errors.hpp"

namespace rt {

std::string_view to_string(Denoiser denoiser) {
    switch (denoiser) {
        case Denoiser::kNone:
            return "none";
        case Denoiser::kBilateral:
            return "bilateral";
        case Denoiser::kAtrous:
            return "atrous";
    }
    return "?";
}

Denoiser denoiser_from_string(const std::string& name) {
    for (Denoiser d : {Denoiser::kNone, Denoiser::kBilateral, Denoiser::kAtrous})
        if (name == to_string(d)) return d;
    throw InputError("--denoiser: expected none, bilateral or atrous, got '" + name + "'");
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
