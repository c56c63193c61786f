#include "edge_stopping.hpp"

#include <algorithm>
#include <cmath>

namespace rt {

Real range_exponent(Real d2, Real s2) {
    if (d2 == 0 || std::isinf(s2)) return 0;
    if (!(s2 > 0)) return kInfinity;
    return d2 / s2;
}

namespace {

// s² = σ² · scale, with σ = ∞ (a guide switched off) infinite for any scale, 0 included.
Real spread(Real sigma, Real scale) {
    return std::isinf(sigma) ? kInfinity : sigma * sigma * scale;
}

}  // namespace

Real edge_stopping_weight(const GuidePixel& p, const GuidePixel& q, const EdgeStopping& sigma) {
    // EXERCISE(ch10.edge_stopping) § Edge-stopping weights
    const Color dc = p.colour - q.colour;
    const Vec3 dn = p.normal - q.normal;
    const Color da = p.albedo - q.albedo;
    const Real dz = p.depth - q.depth;
    const Real z = std::max(p.depth, q.depth);
    return std::exp(-(range_exponent(glm::dot(dc, dc), spread(sigma.colour, p.variance + q.variance)) +
                      range_exponent(glm::dot(dn, dn), spread(sigma.normal, 1)) +
                      range_exponent(dz * dz, spread(sigma.depth, z * z)) +
                      range_exponent(glm::dot(da, da), spread(sigma.albedo, 1))));
    // END EXERCISE
}

std::vector<GuidePixel> guide_pixels(const FeatureBuffers& buffers) {
    std::vector<GuidePixel> guides(buffers.colour.pixel_count());
    for (std::size_t i = 0; i < guides.size(); ++i) {
        const Color& v = buffers.colour_variance.pixels()[i];
        guides[i] = {buffers.colour.pixels()[i], v.r + v.g + v.b, Vec3(buffers.normal.pixels()[i]),
                     buffers.depth.pixels()[i].r, buffers.albedo.pixels()[i]};
    }
    return guides;
}

}  // namespace rt
