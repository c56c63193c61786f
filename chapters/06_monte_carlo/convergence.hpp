// Convergence, measured: for each sampling strategy, renders at 1, 2, 4, …, N samples per pixel and their
// RMSE to a converged reference against their time. An unbiased estimator's RMSE falls like σ / √spp (a
// slope of −1/2 on a log-log plot); the strategies differ in σ and in time per sample, and
// efficiency = 1 / (MSE × time) ranks them by what a second of rendering buys.
//
// The reference is the mean of two independent renders A and B (MIS, many samples), cached as PFM files so
// it is rendered once. Its own noise is not zero: its MSE to the truth is estimated as mean((A − B)²) / 4
// and reported as the floor under which a measured MSE means nothing.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "01_ray_generation/camera.hpp"
#include "04_direct_lighting/render_scene.hpp"
#include "path_tracer.hpp"
#include "rt/core/image.hpp"

namespace rt {

struct Reference {
    Image image;
    double noise_mse = 0;           // estimated mean squared error of the reference itself
    double noise_relative_mse = 0;  // the same in relative MSE: mean((A − B)² / 4 / (ref² + 0.01))
    int spp = 0;
    std::filesystem::path file;
    bool cached = false;  // read from the cache rather than rendered now
    double seconds = 0;   // render time (0 when cached)
};

// The cache file of the reference of `scene` at this size and spp: <folder>/ch06_reference_<scene stem>_
// <W>x<H>_<spp>spp.pfm (and _half.pfm beside it: render A).
std::filesystem::path reference_path(const std::filesystem::path& folder, const Scene& scene, int width,
                                     int height, int spp);

// Reads the cached reference if both files are there and of the right size, else renders A and B with MIS
// (spp / 2 each, seeds 1001 and 1002) and writes them. Throws InputError if the folder is not writable.
Reference converged_reference(const RenderScene& prepared, const PathOptions& options,
                              const PinholeCamera& camera, RenderSettings settings, int spp,
                              const std::filesystem::path& folder);

struct ConvergenceRow {
    SamplingStrategy strategy;
    int spp;
    double rmse;          // against the reference
    double mse;           // rmse², minus the reference's own noise_mse (its estimate of the true MSE)
    double seconds;       // render time (wall clock)
    double cpu_seconds;   // processor time of every thread of the render: what it cost, whoever else ran
    double relative_mse;  // mean((x − r)² / (r² + 0.01)), minus the reference's own noise
};

// Every strategy at spp = 1, 2, 4, …, max_spp with the settings' seed.
std::vector<ConvergenceRow> convergence_study(const RenderScene& prepared, PathOptions options,
                                              const PinholeCamera& camera, RenderSettings settings,
                                              const Reference& reference,
                                              const std::vector<SamplingStrategy>& strategies, int max_spp);

struct EfficiencyRow {
    SamplingStrategy strategy;
    double slope;  // least-squares slope of log RMSE against log spp (−0.5 for a converging estimator)
    double mse;    // at the largest spp
    double relative_mse;         // at the largest spp
    double cpu_seconds;          // at the largest spp
    double efficiency;           // 1 / (mse × cpu_seconds); 0 when mse <= 0 (below the reference's noise)
    double relative_efficiency;  // 1 / (relative_mse × cpu_seconds)
};
std::vector<EfficiencyRow> efficiency_table(const std::vector<ConvergenceRow>& rows);

// Writes the rows as CSV.
void write_convergence_csv(const std::vector<ConvergenceRow>& rows, const std::filesystem::path& csv);
// Draws the log-log plots with gnuplot: RMSE against spp and against processor seconds (the slope −1/2 beside
// them), and the relative MSE against spp (slope −1), as `<stem>_spp.png`, `<stem>_time.png` and
// `<stem>_relative.png`. Returns false (and draws nothing) when
// gnuplot is not installed.
bool plot_convergence(const std::filesystem::path& csv, const std::vector<SamplingStrategy>& strategies,
                      const std::filesystem::path& png_stem, const std::string& title);

// The study of `--converge`: convergence_study for every strategy up to max_spp, its table, the efficiency
// table (efficiency_table), the CSV `csv` and its plots (plot_convergence), printed as the lesson shows them.
void print_convergence_study(const RenderScene& prepared, const PathOptions& options,
                             const PinholeCamera& camera, const RenderSettings& settings,
                             const Reference& ref, int max_spp, const std::string& csv);

struct ConvergenceRequest {
    int max_spp = 1024;
    int reference_spp = 8192;
    std::string cache = ".";                    // the folder of the cached reference
    std::string csv = "ch06_convergence.csv";  // the plots go beside it
};

// `--converge` as chapter 06's executable runs it: the CSV file probed, the converged reference read or
// rendered (and its own noise reported), then print_convergence_study.
void run_convergence_study(const RenderScene& prepared, const PathOptions& options, const PinholeCamera& camera,
                           const RenderSettings& settings, const ConvergenceRequest& request);

}  // namespace rt
