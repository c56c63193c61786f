// Edge-stopping weights: how much a neighbour q may contribute to pixel p, judged by the guides. A filter
// that averages only neighbours whose guides agree with p's smooths the noise within a surface and keeps the
// edges between surfaces (Tomasi and Manduchi 1998's bilateral idea, guided by the feature buffers as in
// Dammertz et al. 2010 and Schied et al. 2017):
//   w(p, q) = w_colour · w_normal · w_depth · w_albedo = exp(−Σ d² / s²),  each guide's term with
//   colour:  d² = |c_p − c_q|²,             s² = σ_c² (Var_p + Var_q)   (a difference in units of the noise)
//   normal:  d² = |n_p − n_q|²,             s² = σ_n²
//   depth:   d² = (z_p − z_q)²,             s² = (σ_z max(z_p, z_q))²   (relative: any scene scale)
//   albedo:  d² = |a_p − a_q|²,             s² = σ_a²
// Equal guides weigh 1 whatever σ (d² = 0); σ = 0 keeps only equal guides; σ = ∞ switches a guide off. A
// zero variance or a zero depth gives s² = 0: the term is then 0 for equal values and ∞ otherwise (weight 0),
// never NaN.
#pragma once

#include <vector>

#include "feature_buffers.hpp"
#include "rt/core/math.hpp"

namespace rt {

// The σ of each guide.
struct EdgeStopping {
    Real colour = 2;          // σ_c, in standard deviations of the noise
    Real normal = 1;          // σ_n
    Real depth = Real(0.2);   // σ_z, a fraction of the depth
    Real albedo = Real(0.3);  // σ_a
};

// What the weights read at one pixel.
struct GuidePixel {
    Color colour{0};
    Real variance = 0;  // of the colour's mean, summed over the three channels (the expected |c_p − c_q|² is
                        // Var_p + Var_q for two noisy estimates of one colour)
    Vec3 normal{0};
    Real depth = 0;
    Color albedo{0};
};

// d² / s², with d² = 0 → 0, s² = ∞ → 0, and s² = 0 → ∞ otherwise: one guide's term of the exponent.
Real range_exponent(Real d2, Real s2);

// w(p, q) above, as one exponential: exp(−Σ d² / s²).
Real edge_stopping_weight(const GuidePixel& p, const GuidePixel& q, const EdgeStopping& sigma);

// Every pixel's guides, row by row from the top left (the colour and variance from buffers.colour and
// buffers.colour_variance).
std::vector<GuidePixel> guide_pixels(const FeatureBuffers& buffers);

}  // namespace rt
