#include "irradiance_study.hpp"

#include <cmath>
#include <cstdio>

namespace rt {

std::vector<IrradianceStudyRow> irradiance_study(const std::vector<int>& sample_counts, int runs) {
    std::vector<IrradianceStudyRow> rows;
    for (const IrradianceCase& c : irradiance_cases()) {
        for (SamplingStrategy s : kAllStrategies) {
            if (s == SamplingStrategy::kBrdf) continue;  // for E (a Lambert BRDF) it is the cosine strategy
            for (PointSet points : kAllPointSets) {
                for (int n : sample_counts) {
                    double sum = 0, sum2 = 0, seconds = 0, variance = 0;
                    for (int r = 0; r < runs; ++r) {
                        const IrradianceEstimate e =
                            estimate_irradiance(c, s, n, std::uint64_t(r) * 7919 + 11, points);
                        const double error = e.mean - c.exact;
                        sum += e.mean;
                        sum2 += error * error;
                        seconds += e.seconds;
                        variance += e.variance;
                    }
                    const double rmse = std::sqrt(sum2 / runs);
                    const double per_run = seconds / runs;
                    rows.push_back({c.name, c.exact, s, points, n, sum / runs, rmse,
                                    std::sqrt(variance / runs), seconds / (double(runs) * n),
                                    rmse > 0 ? 1.0 / (rmse * rmse * std::max(per_run, 1e-12)) : INFINITY});
                }
            }
        }
    }
    return rows;
}

namespace {

// The slope of log RMSE against log N between two rows (a convergence rate: −1/2 for independent points).
double rate(const IrradianceStudyRow& first, const IrradianceStudyRow& last) {
    if (!(first.rmse > 0) || !(last.rmse > 0)) return 0;
    return std::log(last.rmse / first.rmse) / std::log(double(last.samples) / double(first.samples));
}

}  // namespace

// One line per case and strategy: σ of one sample, time per sample, the RMSE of N-sample estimates for
// N = 16, 256, 4096 (independent points) and for N = 4096 stratified and Sobol, the efficiency
// 1 / (MSE × time) of the 4096-sample estimates each way, and each way's rate from N = 16 to 4096.
void print_irradiance_study(int runs) {
    const std::vector<int> counts{16, 256, 4096};
    const auto rows = irradiance_study(counts, runs);
    std::printf(
        "E(p) = integral of L cos theta dw at p = 0, n = +z, against its closed form: %d runs of N samples "
        "per figure; RMSE of one run's estimate\n",
        runs);
    std::printf("%-7s %-8s %9s %9s %9s %8s %9s %9s %9s %9s %9s %9s %9s %9s %6s %6s %6s\n", "case", "strategy",
                "exact", "mean", "sigma", "ns/smp", "RMSE 16", "RMSE 256", "RMSE 4096", "strat.", "sobol",
                "eff.", "strat.", "sobol", "rate", "strat.", "sobol");
    for (std::size_t i = 0; i + 8 < rows.size(); i += 9) {
        // Rows come as (independent: 16, 256, 4096), (stratified: …), (sobol: …) per case and strategy.
        const IrradianceStudyRow* r = &rows[i];
        std::printf(
            "%-7s %-8s %9.6f %9.6f %9.3e %8.1f %9.3e %9.3e %9.3e %9.3e %9.3e %9.3g %9.3g %9.3g %6.2f %6.2f "
            "%6.2f\n",
            r[0].case_name.c_str(), to_string(r[0].strategy).data(), r[0].exact, r[2].mean, r[2].sigma,
            r[2].seconds_per_sample * 1e9, r[0].rmse, r[1].rmse, r[2].rmse, r[5].rmse, r[8].rmse,
            r[2].efficiency, r[5].efficiency, r[8].efficiency, rate(r[0], r[2]), rate(r[3], r[5]),
            rate(r[6], r[8]));
    }
    std::printf(
        "brdf is cosine here (the BRDF of E is Lambert's). eff. = 1 / (RMSE^2 x seconds per estimate) at "
        "N = 4096; rate = slope of log RMSE against log N from 16 to 4096 (0 where the estimate is exact)\n");
}

}  // namespace rt
