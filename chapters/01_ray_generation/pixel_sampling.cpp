#include "pixel_sampling.hpp"

#include <cmath>

namespace rt {

namespace {

// x + u rounds up to x + 1 for u just below 1 once x ≥ 1 (3 + (1 − 2⁻²⁴) is 4 in float), which would put the
// sample in the next pixel; such a coordinate becomes the largest float below c + 1, and no other changes.
Real inside_pixel(Real c, Real p) { return p < c + 1 ? p : std::nextafter(c + 1, c); }
Vec2 inside_pixel(const Vec2& corner, const Vec2& p) {
    return {inside_pixel(corner.x, p.x), inside_pixel(corner.y, p.y)};
}

}  // namespace

Vec2 pixel_sample_point(PixelSampler sampler, int x, int y, int index, int count, Vec2 u) {
    const Vec2 corner{Real(x), Real(y)};
    // EXERCISE(ch01.pixel_sample) § From a pixel to its rays: anti-aliasing
    if (sampler == PixelSampler::kCenter) return corner + Vec2(0.5f);
    const int n = int(std::sqrt(double(count)));
    if (sampler == PixelSampler::kUniform || index >= n * n) return inside_pixel(corner, corner + u);
    const Vec2 stratum{Real(index % n), Real(index / n)};
    return inside_pixel(corner, corner + (stratum + u) / Real(n));
    // END EXERCISE
}

}  // namespace rt
