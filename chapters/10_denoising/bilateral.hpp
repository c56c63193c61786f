// The joint (cross) bilateral filter: each pixel becomes the weighted mean of its window,
//   ĉ(p) = Σ_q w(p, q) c(q) / Σ_q w(p, q),   w(p, q) = exp(−|p − q|² / 2σ_s²) · w_edge(p, q),
// the spatial Gaussian times the edge-stopping weights of the guides (edge_stopping.hpp). "Joint" or "cross":
// the range weights read the feature buffers (and the noise-scaled colour), not only the colour it filters
// (Eisemann and Durand 2004, Petschnigg et al. 2004). The window is |q − p| ≤ ⌈2σ_s⌉ in each axis; pixels
// outside the image take no part (the weights are normalised over those inside).
#pragma once

#include <vector>

#include "edge_stopping.hpp"
#include "feature_buffers.hpp"
#include "rt/core/image.hpp"

namespace rt {

struct BilateralSettings {
    Real spatial = 3;  // σ_s, in pixels
    EdgeStopping edges;
};

// The window's radius, ⌈2σ_s⌉.
int bilateral_radius(const BilateralSettings& settings);

// Pixel (x, y)'s normalised weights w(p, q) / Σ w, row by row over its window of (2r + 1)² pixels (0 outside
// the image).
std::vector<Real> bilateral_weights(const std::vector<GuidePixel>& guides, int width, int height, int x,
                                    int y, const BilateralSettings& settings);

// The filtered image, on `threads` threads (0: one per core); the same bits for any count.
Image bilateral_filter(const FeatureBuffers& buffers, const BilateralSettings& settings, int threads);

}  // namespace rt
