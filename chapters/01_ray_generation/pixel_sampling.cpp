#include "pixel_sampling.hpp"

#include <cmath>
#include <string>

#include "rt/errors.hpp"

namespace rt {

std::string_view to_string(PixelSampler sampler) {
    switch (sampler) {
        case PixelSampler::kCenter: return "center";
        case PixelSampler::kUniform: return "uniform";
        case PixelSampler::kStratified: return "stratified";
    }
    return "?";
}

PixelSampler pixel_sampler_from_string(std::string_view name) {
    for (PixelSampler s : {PixelSampler::kCenter, PixelSampler::kUniform, PixelSampler::kStratified}) {
        if (to_string(s) == name) return s;
    }
    throw InputError("--pixel-sampler: unknown sampler \"" + std::string(name) + "\"; expected center, uniform or stratified");
}

Vec2 pixel_sample_point(PixelSampler sampler, int x, int y, int index, int count, Vec2 u) {
    const Vec2 corner{Real(x), Real(y)};
    // EXERCISE(ch01.pixel_sample)
    if (sampler == PixelSampler::kCenter) return corner + Vec2(0.5f);
    const int n = int(std::sqrt(double(count)));
    if (sampler == PixelSampler::kUniform || index >= n * n) return corner + u;
    const Vec2 stratum{Real(index % n), Real(index / n)};
    // (stratum + u) / n < 1 for u < 1, but rounding can reach 1 exactly: keep the point inside its pixel.
    const Vec2 inside = glm::min((stratum + u) / Real(n), Vec2(kOneMinusEpsilon));
    return corner + inside;
    // END EXERCISE
}

}  // namespace rt
