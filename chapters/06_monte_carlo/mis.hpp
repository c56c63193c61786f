// Multiple importance sampling (Veach & Guibas 1995): one integral, two samplers a and b with densities p_a
// and p_b, n_a and n_b samples. A sample x drawn from a is weighted by w_a(x) and one from b by w_b(x); any
// weights with w_a + w_b = 1 wherever f ≠ 0 keep the estimator unbiased:
//   F = Σ_i w_a(x_i) f(x_i) / (n_a p_a(x_i)) + Σ_j w_b(y_j) f(y_j) / (n_b p_b(y_j)).
// The power heuristic (β = 2) w_a = (n_a p_a)² / ((n_a p_a)² + (n_b p_b)²) leans further toward the sampler
// that is good at x than the balance heuristic (β = 1), which lowers the variance where one of them is bad.
#pragma once

#include <cmath>

#include "rt/core/math.hpp"

namespace rt {

// w_a = (n_a p_a)^β / ((n_a p_a)^β + (n_b p_b)^β), written so that p² cannot overflow, with w_a + w_b = 1
// and no NaN at every edge: p_a = ∞ (a delta, or a light seen edge-on) or 0 against a finite p_b, and two
// equal products (both 0, both ∞).
inline Real mis_weight(Real n_a, Real p_a, Real n_b, Real p_b, int beta) {
    // EXERCISE(ch06.mis_weight) § Light sampling, BRDF sampling, and MIS
    const Real a = n_a * p_a, b = n_b * p_b;
    if (a == b) return Real(0.5);  // also both 0 and both ∞
    if (std::isinf(a)) return 1;
    if (std::isinf(b)) return 0;
    if (!(a > 0)) return 0;
    if (!(b > 0)) return 1;
    const Real r = b / a;
    return Real(1) / (1 + (beta == 2 ? r * r : r));
    // END EXERCISE
}

// The power heuristic with one sample of each: w_a = p_a² / (p_a² + p_b²).
inline Real power_heuristic(Real p_a, Real p_b) {
    return mis_weight(1, p_a, 1, p_b, 2);
}

// The balance heuristic with one sample of each: w_a = p_a / (p_a + p_b).
inline Real balance_heuristic(Real p_a, Real p_b) {
    return mis_weight(1, p_a, 1, p_b, 1);
}

}  // namespace rt
