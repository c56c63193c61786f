// A piecewise-constant density on [0, 1): n cells of equal width, cell i's density proportional to its
// weight w_i. Its cumulative distribution is a polyline through CDF_i = Σ_{j<i} w_j / Σ_j w_j; inverting it
// draws x with density p(x) = w_i / (Σ_j w_j / n) in cell i. Weights all 0 give the uniform density.
#pragma once

#include <vector>

#include "rt/core/math.hpp"

namespace rt {

class Distribution1D {
  public:
    struct Sample {
        Real x = 0;    // in [0, 1)
        Real pdf = 0;  // p(x), a density over [0, 1)
        int cell = 0;  // the cell x fell in
    };

    // Weights finite and >= 0, at least one of them.
    explicit Distribution1D(std::vector<double> weights);

    // Inverts the CDF at u in [0, 1): the cell i with CDF_i <= u < CDF_{i+1} (never one of weight 0), then
    // linearly within it.
    Sample sample(Real u) const;
    // p(x) in cell i.
    Real pdf(int cell) const;
    // ∫ density over [0, 1) before normalising: Σ w_i / n.
    double integral() const { return integral_; }
    int size() const { return int(weights_.size()); }

  private:
    std::vector<double> weights_;
    std::vector<double> cdf_;  // n + 1 entries, from 0 to 1
    double integral_ = 0;
};

}  // namespace rt
