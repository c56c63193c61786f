// Where inside a pixel each sample's ray passes: the centre, a uniformly jittered point, or a jittered
// point in its own stratum. Pixel (x, y) covers film points [x, x+1) × [y, y+1).
#pragma once

#include "rt/core/enum_names.hpp"
#include "rt/core/math.hpp"

namespace rt {

enum class PixelSampler { kCenter, kUniform, kStratified };

constexpr auto names_of(PixelSampler) {
    return enum_names<PixelSampler>("--pixel-sampler", {{PixelSampler::kCenter, "center"},
                                                        {PixelSampler::kUniform, "uniform"},
                                                        {PixelSampler::kStratified, "stratified"}});
}

// The film point of sample `index` of `count` in pixel (x, y), from a uniform random pair u in [0, 1)².
// center: the pixel's centre. uniform: a uniform point of the pixel. stratified: the pixel is cut into n×n
// strata, n = ⌊√count⌋ (the largest square grid count fills), and each of the first n² samples is uniform in
// a stratum of its own; the samples past n² are uniform over the pixel.
Vec2 pixel_sample_point(PixelSampler sampler, int x, int y, int index, int count, Vec2 u);

}  // namespace rt
