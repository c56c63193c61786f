// The depth glass needs, measured: the scene rendered with a fixed maximum depth D (chapter 05's depth rule)
// for each D, its RMSE and relative MSE against a converged reference (Russian roulette, unbiased), and its
// time. Light that needs more than D bounces is lost: behind glass a path spends two bounces per sphere it
// crosses (in and out) and more on internal reflections, so glass needs a deeper cut than diffuse walls.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "06_monte_carlo/path_tracer.hpp"
#include "rt/core/image.hpp"
#include "rt/core/scene.hpp"
#include "rt/render/render_loop.hpp"

namespace rt {

struct GlassDepthRow {
    int max_depth;
    double rmse;
    double relative_mse;
    double mean_error;  // the bias: negative, light lost
    double seconds;
    std::uint64_t rays;
};

// The reference: `spp` samples with Russian roulette, read from `cache` when a file of that name and size is
// there, else rendered and written: <folder>/ch07_reference_<scene stem>_<W>x<H>_<spp>spp.pfm.
Image glass_depth_reference(const Scene& scene, const RenderSettings& settings, const PathOptions& options,
                            int spp, const std::filesystem::path& folder, bool& cached);

std::vector<GlassDepthRow> glass_depth_study(const Scene& scene, const RenderSettings& settings,
                                             const PathOptions& options, const Image& reference,
                                             const std::vector<int>& depths);

// The rows as CSV (max_depth,spp,rmse,relative_mse,mean_error,seconds,rays), `spp` samples per pixel each.
// Throws InputError when the file cannot be written.
void write_glass_depth_csv(const std::vector<GlassDepthRow>& rows, int spp, const std::filesystem::path& csv);

struct GlassDepthRequest {
    std::vector<int> depths{1, 2, 4, 8, 16};
    int reference_spp = 4096;
    std::string cache = ".";  // the folder of the cached reference
    std::string csv;          // empty: no CSV
};

// `--depth-study` as chapter 07's executable runs it: the CSV file probed, the reference read or rendered,
// every depth measured, the table on stdout and, when asked, as CSV.
void run_glass_depth_study(const Scene& scene, const RenderSettings& settings, const PathOptions& options,
                           const GlassDepthRequest& request);

}  // namespace rt
