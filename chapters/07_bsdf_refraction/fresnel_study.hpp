// Schlick's approximation against the exact Fresnel reflectance, measured: over n angles θ evenly spread in
// [0°, 90°], the largest and the mean |R_schlick − R_exact|, for light entering glass (η = ior) and leaving
// it (η = 1 / ior); and the time of one evaluation of each (the median of several timed sweeps).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "rt/core/math.hpp"
#include "rt/core/scene.hpp"

namespace rt {

struct FresnelStudyRow {
    Real eta;
    double max_error;
    double mean_error;
    double max_error_angle;  // degrees, where the largest error is
    double exact_ns;         // per evaluation
    double schlick_ns;
};

std::vector<FresnelStudyRow> fresnel_study(Real ior, int angles, int repeats);

// θ (degrees), then exact and Schlick R for η = ior and for η = 1 / ior, one line per angle.
void write_fresnel_csv(Real ior, int angles, const std::filesystem::path& csv);

// `--fresnel-study` as chapter 07's executable runs it: the study at the index of the scene's first dielectric
// (1.5 without one), 100 001 angles, 15 timed sweeps, its table on stdout; with `csv`, R(θ) both ways there.
void run_fresnel_study(const Scene& scene, const std::string& csv);

}  // namespace rt
