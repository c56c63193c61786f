// The edge-avoiding à-trous wavelet filter (Dammertz, Sewtz, Hanika and Lensch 2010), with the variance
// guidance of SVGF (Schied et al. 2017). A wide blur built from small ones: level i convolves with the 5×5
// B3-spline kernel h(j, k) = h_j h_k, h = (1, 4, 6, 4, 1)/16, its taps 2^i pixels apart (the "holes", à
// trous), each tap also weighed by the edge-stopping weights (edge_stopping.hpp):
//   c_{i+1}(p) = Σ_q h(q) w_i(p, q) c_i(p + 2^i q) / Σ_q h(q) w_i(p, q).
// Five levels reach as far as a 125×125 kernel at 5 · 25 taps a pixel. The colour weight reads the level's
// own colours c_i and their variances, which each level filters along as the variance of its weighted mean
// of independent values, so the edge stopping on colour tightens as the noise goes. Taps outside the image take no part.
#pragma once

#include <array>
#include <vector>

#include "edge_stopping.hpp"
#include "feature_buffers.hpp"
#include "rt/core/image.hpp"

namespace rt {

// The B3-spline's taps, h_{−2} … h_2.
inline constexpr std::array<Real, 5> kB3Taps{Real(1) / 16, Real(1) / 4, Real(3) / 8, Real(1) / 4,
                                             Real(1) / 16};

struct AtrousSettings {
    int levels = 5;
    EdgeStopping edges;
};

// One level at pixel (x, y), taps `step` pixels apart: the pixel of `level` with its colour c_{i+1}(p) and
// variance Var_{i+1}(p) (its other guides as they were). Given `weights` (25 entries), writes there the
// normalised weights h w / Σ h w of its taps, row by row (0 outside the image).
GuidePixel atrous_pixel(const std::vector<GuidePixel>& level, int width, int height, int x, int y, int step,
                        const EdgeStopping& edges, Real* weights = nullptr);

// The filtered image: `settings.levels` levels with steps 1, 2, 4, …, on `threads` threads (0: one per core);
// the same bits for any count.
Image atrous_filter(const FeatureBuffers& buffers, const AtrousSettings& settings, int threads);

}  // namespace rt
