#include "distribution_2d.hpp"

#include <stdexcept>

namespace rt {
namespace {

std::vector<Distribution1D> rows_of(const std::vector<double>& weights, int nu, int nv) {
    if (nu < 1 || nv < 1 || weights.size() != std::size_t(nu) * std::size_t(nv))
        throw std::invalid_argument("Distribution2D: weights are not nu x nv");
    std::vector<Distribution1D> rows;
    rows.reserve(std::size_t(nv));
    for (int j = 0; j < nv; ++j) {
        const auto first = weights.begin() + std::ptrdiff_t(j) * nu;
        rows.emplace_back(std::vector<double>(first, first + nu));
    }
    return rows;
}

std::vector<double> integrals_of(const std::vector<Distribution1D>& rows) {
    std::vector<double> integrals;
    for (const Distribution1D& row : rows) integrals.push_back(row.integral());
    return integrals;
}

}  // namespace

Distribution2D::Distribution2D(const std::vector<double>& weights, int nu, int nv)
    : conditional_(rows_of(weights, nu, nv)), marginal_(integrals_of(conditional_)) {}

Distribution2D::Sample Distribution2D::sample(Vec2 u) const {
    const Distribution1D::Sample v = marginal_.sample(u.y);
    const Distribution1D::Sample along = conditional_[std::size_t(v.cell)].sample(u.x);
    return {Vec2(along.x, v.x), v.pdf * along.pdf, along.cell, v.cell};
}

Real Distribution2D::pdf(int i, int j) const {
    // p(v) p(u | v) = (row integral / total) · (w / row integral) = w / total; a row of weight 0 has p(v) = 0
    // (its conditional is uniform, never 0/0).
    return marginal_.pdf(j) * conditional_[std::size_t(j)].pdf(i);
}

}  // namespace rt
