// Chapter 01's two renders: the picture (ray directions over the sky, split by the edge) and the coverage
// image of the edge, whose exact value is known, for measuring anti-aliasing (the study and its table).
#pragma once

#include <string>
#include <vector>

#include "camera.hpp"
#include "edge_coverage.hpp"
#include "pixel_sampling.hpp"
#include "rt/render/render_loop.hpp"

namespace rt {

// Inside the edge each ray shows its direction's colour; outside, the sky.
RenderResult render_directions(const PinholeCamera& camera, const FilmEdge& edge, PixelSampler sampler,
                               const RenderSettings& settings);

// 1 where the ray is inside the edge, 0 outside, averaged over each pixel's samples.
RenderResult render_coverage(const PinholeCamera& camera, const FilmEdge& edge, PixelSampler sampler,
                             const RenderSettings& settings);

// RMSE of the rendered coverage against the exact coverage, over the pixels the edge crosses
// (0 < exact < 1): the error anti-aliasing removes.
double edge_rmse(const Image& coverage, const FilmEdge& edge);

struct AntialiasingRow {
    PixelSampler sampler;
    int spp;
    double edge_rmse;
    double seconds;
};

// Every sampler at each sample count, timed, against the exact coverage.
std::vector<AntialiasingRow> antialiasing_study(const PinholeCamera& camera, const FilmEdge& edge,
                                                RenderSettings settings, const std::vector<int>& spp_values);

// `--aa-study` as the executable runs it: the CSV file probed, the study at 1, 4, 16, 64 and 256 spp, its
// table on stdout and, when `csv` is not empty, as CSV there.
void run_antialiasing_study(const PinholeCamera& camera, const FilmEdge& edge, const RenderSettings& settings,
                            const std::string& csv);

}  // namespace rt
