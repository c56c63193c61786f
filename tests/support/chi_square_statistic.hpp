// The chi-square goodness-of-fit test of a sampler, without a test framework: the statistic and its p-value,
// the cells of the sphere, the counts a pdf expects in them and the counts a sampler draws. The tests use it
// through chi_square.hpp (which adds the Catch2 checks); the sampler view (chapters/09_participating_media/
// sampler_view) shows the same histogram and verdict in a browser. Header-only: each program includes it
// once.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "rt/core/math.hpp"
#include "rt/core/random.hpp"

namespace rt::test {

// The samples of one direction test.
inline constexpr int kDirectionSamples = 1000000;

// The level for each of a program's `tests` chi-square tests: all pass together with probability 1 − α.
inline double sidak_level(int tests, double alpha = 0.01) {
    return 1 - std::pow(1 - alpha, 1.0 / tests);
}

// The regularized upper incomplete gamma function Q(a, x) = Γ(a, x) / Γ(a): by its power series for x < a +
// 1, by its continued fraction (modified Lentz) otherwise.
inline double gamma_q(double a, double x) {
    if (x <= 0) return 1;
    const double log_prefactor = a * std::log(x) - x - std::lgamma(a);
    if (x < a + 1) {
        // P(a, x) = x^a e^-x / Γ(a) Σ_n x^n / (a (a+1) … (a+n)).
        double term = 1 / a, sum = term;
        for (int n = 1; n < 100000; ++n) {
            term *= x / (a + n);
            sum += term;
            if (term < sum * 1e-15) break;
        }
        return 1 - sum * std::exp(log_prefactor);
    }
    // Q(a, x) = x^a e^-x / Γ(a) · 1 / (x + 1 − a − 1·(1 − a) / (x + 3 − a − 2·(2 − a) / (x + 5 − a − …))).
    const double tiny = 1e-300;
    double b = x + 1 - a, c = 1 / tiny, d = 1 / b, h = d;
    for (int i = 1; i < 100000; ++i) {
        const double an = -i * (i - a);
        b += 2;
        d = an * d + b;
        if (std::abs(d) < tiny) d = tiny;
        c = b + an / c;
        if (std::abs(c) < tiny) c = tiny;
        d = 1 / d;
        const double delta = d * c;
        h *= delta;
        if (std::abs(delta - 1) < 1e-15) break;
    }
    return std::exp(log_prefactor) * h;
}

// P(χ² >= statistic) for `dof` degrees of freedom.
inline double chi_square_p_value(double statistic, int dof) {
    return gamma_q(dof / 2.0, statistic / 2.0);
}

struct ChiSquare {
    double statistic = 0;
    int dof = 0;
    double p_value = 1;
    int samples = 0;            // N (test_directions)
    double expected_total = 0;  // Σ expected = N ∫ pdf: N when the pdf integrates to 1
    double expected_upper = 0;  // the same over z > 0 only
    long long bad_samples = 0;  // not finite, not unit length, or where the pdf is 0
    long long lost = 0;         // the sampler gave no direction (Drawn::lost): a BSDF's lost samples
};

// Counts in cells against expected counts. Cells are taken from the smallest expected count up and pooled
// until the pool expects at least 5; each pool is one cell of the statistic, and a last pool still under 5
// joins the one before it. Cells expecting nothing (where the pdf is 0) are pooled too: a sample that lands
// where the pdf is 0 is caught on its own, as a bad sample.
inline ChiSquare chi_square(const std::vector<double>& observed, const std::vector<double>& expected) {
    std::vector<std::size_t> order(expected.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](auto a, auto b) { return expected[a] < expected[b]; });
    ChiSquare r;
    std::vector<std::pair<double, double>> cells;  // (observed, expected)
    double pool_observed = 0, pool_expected = 0;
    for (std::size_t i : order) {
        r.expected_total += expected[i];
        pool_observed += observed[i];
        pool_expected += std::max(0.0, expected[i]);
        if (pool_expected >= 5) {
            cells.push_back({pool_observed, pool_expected});
            pool_observed = pool_expected = 0;
        }
    }
    if (!cells.empty()) {
        cells.back().first += pool_observed;
        cells.back().second += pool_expected;
    }
    for (const auto& [o, e] : cells) r.statistic += (o - e) * (o - e) / e;
    r.dof = std::max(1, int(cells.size()) - 1);
    r.p_value = chi_square_p_value(r.statistic, r.dof);
    return r;
}

// Cells of the unit sphere in (z, φ): z = cos θ in nz equal steps over [−1, 1], φ in nphi steps over [0, 2π);
// equal solid angle 4π / (nz nphi) each (dω = dz dφ).
struct SphereGrid {
    int nz = 48;
    int nphi = 96;
    int cells() const { return nz * nphi; }
    int cell_of(const Vec3& w) const {
        const double z = std::clamp(double(w.z), -1.0, 1.0);
        double phi = std::atan2(double(w.y), double(w.x));
        if (phi < 0) phi += 2 * std::numbers::pi;
        const int i = std::min(nz - 1, int((z + 1) / 2 * nz));
        const int j = std::min(nphi - 1, int(phi / (2 * std::numbers::pi) * nphi));
        return i * nphi + j;
    }
};

using DirectionPdf = std::function<double(const Vec3&)>;

// ∫ pdf dz dφ over [z0, z1] × [p0, p1] by adaptive Simpson's rule: the 3×3-point rule on the rectangle
// against the sum of it on the four quarters; where they differ by more than 15 tol (an edge of a light, the
// rim of a cone), each quarter is refined in turn, up to `depth` halvings. Steps in the pdf (which Simpson's
// rule alone gets wrong by a fraction of a cell) are thus narrowed to 2^-depth of the rectangle.
inline double adaptive_simpson(const DirectionPdf& pdf, double z0, double z1, double p0, double p1,
                               double tol, int depth) {
    double f[5][5];
    for (int a = 0; a < 5; ++a) {
        const double z = z0 + (z1 - z0) * a / 4, r = std::sqrt(std::max(0.0, 1 - z * z));
        for (int b = 0; b < 5; ++b) {
            const double phi = p0 + (p1 - p0) * b / 4;
            f[a][b] = pdf(Vec3(Real(r * std::cos(phi)), Real(r * std::sin(phi)), Real(z)));
        }
    }
    constexpr double w[3] = {1, 4, 1};
    auto rule = [&](int a0, int b0, int step, double area) {
        double sum = 0;
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) sum += w[a] * w[b] * f[a0 + a * step][b0 + b * step];
        return sum * area / 36;
    };
    const double area = (z1 - z0) * (p1 - p0);
    const double whole = rule(0, 0, 2, area);
    const double quarters =
        rule(0, 0, 1, area / 4) + rule(2, 0, 1, area / 4) + rule(0, 2, 1, area / 4) + rule(2, 2, 1, area / 4);
    const double allowed =
        15 * std::max(tol, 1e-5 * std::abs(quarters));  // absolute, or relative to the part
    if (depth == 0 || std::abs(quarters - whole) <= allowed) return quarters + (quarters - whole) / 15;
    const double zm = (z0 + z1) / 2, pm = (p0 + p1) / 2;
    return adaptive_simpson(pdf, z0, zm, p0, pm, tol / 4, depth - 1) +
           adaptive_simpson(pdf, zm, z1, p0, pm, tol / 4, depth - 1) +
           adaptive_simpson(pdf, z0, zm, pm, p1, tol / 4, depth - 1) +
           adaptive_simpson(pdf, zm, z1, pm, p1, tol / 4, depth - 1);
}

// N ∫ pdf dω over each cell: each cell cut into 2 × 2 rectangles (so no feature hides between the points of
// the first rule), each integrated adaptively.
inline std::vector<double> expected_counts(const SphereGrid& grid, const DirectionPdf& pdf, double n) {
    const double dz = 2.0 / grid.nz, dphi = 2 * std::numbers::pi / grid.nphi;
    constexpr int kSplit = 2;
    std::vector<double> expected(std::size_t(grid.cells()));
    for (int i = 0; i < grid.nz; ++i) {
        for (int j = 0; j < grid.nphi; ++j) {
            double sum = 0;
            for (int a = 0; a < kSplit; ++a) {
                for (int b = 0; b < kSplit; ++b) {
                    const double z0 = -1 + dz * (i + double(a) / kSplit),
                                 p0 = dphi * (j + double(b) / kSplit);
                    sum += adaptive_simpson(pdf, z0, z0 + dz / kSplit, p0, p0 + dphi / kSplit, 1e-9, 8);
                }
            }
            expected[std::size_t(i * grid.nphi + j)] = n * sum;
        }
    }
    return expected;
}

// What a sampler gives: a direction and the pdf it reports for it (for a bare warp, its pdf function's).
struct Drawn {
    Vec3 w;
    double pdf;
    bool lost = false;  // no direction: a BSDF sample that left on the wrong side (counted, not binned)
};
using DirectionSampler = std::function<Drawn(Vec2)>;

// What a sampler drew, cell by cell of the grid, beside what its pdf expects there.
struct DirectionHistogram {
    SphereGrid grid;
    std::vector<double> observed, expected;  // per cell, cell i * grid.nphi + j
    long long bad = 0, lost = 0;             // as ChiSquare::bad_samples and ChiSquare::lost
};

// Draws `samples` directions (seeded: Pcg32(seed, 17)) and counts them in the cells of the sphere, beside
// N ∫_cell pdf dω. Samples that are not finite unit vectors, or where the pdf is 0, are counted as bad (and
// must not exist); samples the sampler reports lost are counted apart (the cells then expect N ∫ pdf < N in
// all).
inline DirectionHistogram histogram_directions(const DirectionSampler& sampler, const DirectionPdf& pdf,
                                               std::uint64_t seed, int samples = kDirectionSamples) {
    DirectionHistogram h;
    h.observed.assign(std::size_t(h.grid.cells()), 0);
    Pcg32 rng(seed, 17);
    for (int s = 0; s < samples; ++s) {
        const Drawn d = sampler(rng.next_vec2());
        if (d.lost) {
            ++h.lost;
            continue;
        }
        const Vec3 w = d.w;
        // On the horizon z = 0 exactly a lobe's density is 0 but its inversion may land there (u = 0 for
        // cos α = u^(1/(e+1)), which 1 − u never reaches): the edge of a support above it, not outside it.
        const bool on_horizon = w.z == 0 && pdf(glm::normalize(Vec3(w.x, w.y, 1))) > 0;
        if (!is_finite(w) || std::abs(glm::length(w) - 1) > 1e-4f || !(pdf(w) > 0 || on_horizon)) {
            ++h.bad;
            continue;
        }
        h.observed[std::size_t(h.grid.cell_of(w))] += 1;
    }
    h.expected = expected_counts(h.grid, pdf, samples);
    return h;
}

// The chi-square test of a histogram of `samples` directions (histogram_directions).
inline ChiSquare test_histogram(const DirectionHistogram& h, int samples) {
    ChiSquare r = chi_square(h.observed, h.expected);
    r.bad_samples = h.bad;
    r.lost = h.lost;
    r.samples = samples;
    for (int i = h.grid.nz / 2; i < h.grid.nz; ++i)
        for (int j = 0; j < h.grid.nphi; ++j)
            r.expected_upper += h.expected[std::size_t(i * h.grid.nphi + j)];
    return r;
}

// Draws `samples` directions and tests them against the pdf (histogram_directions, then test_histogram).
inline ChiSquare test_directions(const DirectionSampler& sampler, const DirectionPdf& pdf, std::uint64_t seed,
                                 int samples = kDirectionSamples) {
    return test_histogram(histogram_directions(sampler, pdf, seed, samples), samples);
}

// A sampler of distances along a segment [0, t_max) (chapter 09's equiangular sampling): t from u, and the
// density it reports for t.
struct SegmentWarp {
    std::string name;
    double t_max;
    std::function<double(double)> sample, pdf;
};

// What such a sampler drew in `cells` equal cells of [0, t_max), beside N ∫_cell pdf dt (the midpoint rule,
// 64 points a cell: none at an end, where the pdf of [0, t_max) stops). A t outside [0, t_max), or where the
// pdf is 0, is bad. Seeded: Pcg32(seed, 17).
struct SegmentHistogram {
    std::vector<double> observed, expected;
    long long bad = 0;
};
inline SegmentHistogram histogram_segment(const SegmentWarp& warp, std::uint64_t seed, int samples,
                                          int cells = 200) {
    SegmentHistogram h;
    h.observed.assign(std::size_t(cells), 0);
    Pcg32 rng(seed, 17);
    for (int s = 0; s < samples; ++s) {
        const double t = warp.sample(double(rng.next_real()));
        if (!(t >= 0 && t < warp.t_max) || !(warp.pdf(t) > 0)) {
            ++h.bad;
            continue;
        }
        h.observed[std::size_t(std::min(cells - 1, int(t / warp.t_max * cells)))] += 1;
    }
    constexpr int kSteps = 64;
    const double width = warp.t_max / cells, step = width / kSteps;
    for (int c = 0; c < cells; ++c) {
        double sum = 0;
        for (int k = 0; k < kSteps; ++k) sum += warp.pdf(c * width + (k + 0.5) * step);
        h.expected.push_back(samples * sum * step);
    }
    return h;
}

// What each failed check of a fit says about the derivation behind it (a test of any correct answer: the
// samples are compared with the density, never with one formula).
inline constexpr const char* kOutsideSupport =
    "samples outside the density's support, or not unit vectors: a wrong range (a sign, a missing square "
    "root) or a density that forgets where it is 0?";
inline constexpr const char* kNotNormalised =
    "the density is not normalised: its integral over the sphere is not 1 (a constant forgotten, or the "
    "Jacobian of a change of variables)?";
inline constexpr const char* kHistogramDiffers =
    "the histogram differs from the density: a wrong inversion of the cumulative distribution, or a "
    "Jacobian missing (from the sampler or the density)?";

// What keeps a fitted sample from passing at `level`, one line each (none: it passes). Every sampler: no
// bad sample, p > level. One that loses no sample: its pdf integrates to 1 within 1e-3. One that may lose
// samples (a BSDF whose sample leaves on the wrong side): its pdf integrates to at most 1 (within the 1e-3 of
// the integration), and to what was not lost: |lost / N − (1 − ∫ pdf)| within the same 1e-3 plus 5 binomial
// standard deviations.
inline std::vector<std::string> fit_problems(const ChiSquare& r, double level, bool may_lose) {
    const auto shown = [](auto x) {
        char text[32];
        std::snprintf(text, sizeof text, "%.4g", double(x));
        return std::string(text);
    };
    std::vector<std::string> problems;
    const double n = r.samples, integral = r.expected_total / n, lost = double(r.lost) / n;
    if (r.bad_samples != 0)
        problems.push_back(std::to_string(r.bad_samples) + " bad samples: " + kOutsideSupport);
    if (!may_lose && !(std::abs(integral - 1) <= 1e-3))
        problems.push_back("the pdf integrates to " + shown(integral) + ": " + kNotNormalised);
    if (may_lose) {
        const double sigma = std::sqrt(std::max(lost * (1 - lost), 1 / n) / n);
        if (!(integral <= 1 + 1e-3))
            problems.push_back("the pdf integrates to " + shown(integral) + " > 1: " + kNotNormalised);
        if (!(std::abs(lost - (1 - integral)) <= 1e-3 + 5 * sigma))
            problems.push_back("lost " + shown(lost) + " of the samples, but the pdf leaves out " +
                               shown(1 - integral));
    }
    if (!(r.p_value > level))
        problems.push_back("p = " + shown(r.p_value) + " is not above the level " + shown(level) + ": " +
                           kHistogramDiffers);
    return problems;
}

}  // namespace rt::test
