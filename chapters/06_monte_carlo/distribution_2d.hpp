// A piecewise-constant density on [0, 1)²: a grid of nu × nv cells with weights w(i, j). It is drawn as a
// marginal and a conditional, p(u, v) = p(v) · p(u | v):
//   the marginal over rows,       p(v) ∝ Σ_i w(i, j)        (a Distribution1D of the rows' sums),
//   the conditional within row j, p(u | v) ∝ w(i, j)         (one Distribution1D per row),
// so p(u, v) = w(i, j) / (Σ_ij w(i, j) / (nu nv)). Two numbers draw a point: the first picks the row, the
// second the cell within it.
#pragma once

#include <vector>

#include "distribution_1d.hpp"
#include "rt/core/math.hpp"

namespace rt {

class Distribution2D {
  public:
    struct Sample {
        Vec2 uv{0};    // in [0, 1)²
        Real pdf = 0;  // p(u, v), a density over [0, 1)²
        int i = 0, j = 0;  // the cell: column i, row j
    };

    // `weights` row by row (row j holds w(0, j) … w(nu − 1, j)), finite and >= 0.
    Distribution2D(const std::vector<double>& weights, int nu, int nv);

    Sample sample(Vec2 u) const;
    // p(u, v) in cell (i, j).
    Real pdf(int i, int j) const;
    // ∫ over [0, 1)² of the weights as a density: Σ w / (nu nv). 0 when every weight is.
    double integral() const { return marginal_.integral(); }
    int columns() const { return conditional_.front().size(); }
    int rows() const { return marginal_.size(); }

  private:
    std::vector<Distribution1D> conditional_;  // one per row
    Distribution1D marginal_;
};

}  // namespace rt
