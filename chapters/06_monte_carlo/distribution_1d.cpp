#include "distribution_1d.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rt {

Distribution1D::Distribution1D(std::vector<double> weights) : weights_(std::move(weights)) {
    if (weights_.empty()) throw std::invalid_argument("Distribution1D: no weights");
    const double n = double(weights_.size());
    cdf_.assign(weights_.size() + 1, 0);
    for (std::size_t i = 0; i < weights_.size(); ++i) cdf_[i + 1] = cdf_[i] + weights_[i] / n;
    integral_ = cdf_.back();
    for (std::size_t i = 1; i < cdf_.size(); ++i)
        cdf_[i] = integral_ > 0 ? cdf_[i] / integral_ : double(i) / n;
    cdf_.back() = 1;
}

Distribution1D::Sample Distribution1D::sample(Real u) const {
    // The first CDF entry above u ends the cell; a cell of weight 0 has CDF_i = CDF_{i+1} and is never found.
    const auto above = std::upper_bound(cdf_.begin(), cdf_.end(), double(u));
    const int cell = std::clamp(int(above - cdf_.begin()) - 1, 0, size() - 1);
    const double width = cdf_[std::size_t(cell) + 1] - cdf_[std::size_t(cell)];
    const double within = width > 0 ? (double(u) - cdf_[std::size_t(cell)]) / width : 0.5;
    // x stays inside its cell: rounded to Real, (cell + 0.99999999) / n may be the next cell's start.
    const Real end = std::nextafter(Real(double(cell + 1) / double(size())), Real(0));
    const Real x = std::min(Real((cell + std::clamp(within, 0.0, 1.0)) / double(size())), end);
    return {x, pdf(cell), cell};
}

Real Distribution1D::pdf(int cell) const {
    return integral_ > 0 ? Real(weights_[std::size_t(cell)] / integral_) : Real(1);
}

}  // namespace rt
