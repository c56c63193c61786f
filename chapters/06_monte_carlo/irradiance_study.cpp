#include "irradiance_study.hpp"

#include <cmath>

namespace rt {

std::vector<IrradianceStudyRow> irradiance_study(const std::vector<int>& sample_counts, int runs) {
    std::vector<IrradianceStudyRow> rows;
    for (const IrradianceCase& c : irradiance_cases()) {
        for (SamplingStrategy s : kAllStrategies) {
            if (s == SamplingStrategy::kBrdf) continue;  // for E (a Lambert BRDF) it is the cosine strategy
            for (bool stratified : {false, true}) {
                for (int n : sample_counts) {
                    double sum = 0, sum2 = 0, seconds = 0, variance = 0;
                    for (int r = 0; r < runs; ++r) {
                        const IrradianceEstimate e =
                            estimate_irradiance(c, s, n, std::uint64_t(r) * 7919 + 11, stratified);
                        const double error = e.mean - c.exact;
                        sum += e.mean;
                        sum2 += error * error;
                        seconds += e.seconds;
                        variance += e.variance;
                    }
                    const double rmse = std::sqrt(sum2 / runs);
                    const double per_run = seconds / runs;
                    rows.push_back({c.name, c.exact, s, stratified, n, sum / runs, rmse,
                                    std::sqrt(variance / runs), seconds / (double(runs) * n),
                                    rmse > 0 ? 1.0 / (rmse * rmse * std::max(per_run, 1e-12)) : INFINITY});
                }
            }
        }
    }
    return rows;
}

}  // namespace rt
