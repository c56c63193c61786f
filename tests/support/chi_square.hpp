// The chi-square goodness-of-fit test shared by the test programs of chapters 06, 07 and 08 (header-only:
// each program includes it once). A sampler draws directions; they are counted in cells of the unit sphere
// and compared with the counts its pdf expects there, N ∫_cell pdf dω, integrated numerically. Each program
// runs several such tests and states how many: sidak_level(m) is the Šidák-corrected level
// α' = 1 − (1 − α)^(1/m) at which each is run, so that all m pass together with probability 1 − α when the
// samplers are right. This file holds the Catch2 checks of a fit; the statistic, the cells and the counts are
// chi_square_statistic.hpp's, which the sampler view shares.
#pragma once

#include <catch2/catch.hpp>
#include <string>
#include <vector>

#include "chi_square_statistic.hpp"

namespace rt::test {

// The sample passes at the corrected `level` (sidak_level): fit_problems finds nothing (no bad sample, and the
// pdf integrates to 1 within 1e-3).
inline void require_fit(const ChiSquare& r, double level) {
    INFO("chi-square " << r.statistic << ", " << r.dof << " dof, p = " << r.p_value << " (level " << level
                       << "), expected total " << r.expected_total << ", bad samples " << r.bad_samples);
    const std::vector<std::string> problems = fit_problems(r, level, false);
    for (const std::string& problem : problems) UNSCOPED_INFO(problem);
    CHECK(problems.empty());
}

// For a sampler that may lose samples (a BSDF whose sample leaves on the wrong side): fit_problems finds
// nothing (no bad sample, the pdf integrates to at most 1 and to what was not lost).
inline void require_fit_with_losses(const ChiSquare& r, double level) {
    INFO("chi-square " << r.statistic << ", " << r.dof << " dof, p = " << r.p_value << " (level " << level
                       << "), integral of the pdf " << r.expected_total / r.samples << ", lost "
                       << double(r.lost) / r.samples << ", bad samples " << r.bad_samples);
    const std::vector<std::string> problems = fit_problems(r, level, true);
    for (const std::string& problem : problems) UNSCOPED_INFO(problem);
    CHECK(problems.empty());
}

}  // namespace rt::test
