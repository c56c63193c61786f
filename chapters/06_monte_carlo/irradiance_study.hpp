// The irradiance integral as the lesson's first experiment: for each case and strategy, the RMSE of the
// N-sample estimate over many independent runs (seeds), against the exact E, for growing N — with
// independent, stratified and Owen-scrambled Sobol points.
#pragma once

#include <vector>

#include "irradiance_estimators.hpp"

namespace rt {

struct IrradianceStudyRow {
    std::string case_name;
    double exact;
    SamplingStrategy strategy;
    PointSet points;
    int samples;                // N per estimate
    double mean;                // of all runs' estimates
    double rmse;                // of one run's estimate, against exact
    double sigma;               // per-sample standard deviation (independent points: rmse ≈ σ / √N)
    double seconds_per_sample;  // the runs' time over their samples
    double efficiency;          // 1 / (rmse² × seconds per run)
};

std::vector<IrradianceStudyRow> irradiance_study(const std::vector<int>& sample_counts, int runs);

// The study of `--irradiance` on stdout: for each case and strategy, σ of one sample, time per sample, the
// RMSE of N-sample estimates for N = 16, 256, 4096 with independent points, the RMSE at N = 4096 with
// stratified and with Sobol points, the efficiency 1 / (MSE × time) of the 4096-sample estimates each way,
// and each way's convergence rate: the slope of log RMSE against log N from 16 to 4096 (−1/2 for independent
// points); `runs` runs per figure.
void print_irradiance_study(int runs);

}  // namespace rt
