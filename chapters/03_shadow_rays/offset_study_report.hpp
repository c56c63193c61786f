// `--offset-study` as chapter 03's executable runs it: the scene at each of the study's scales, every offset
// method, the table on stdout and, when asked, the same table as CSV.
#pragma once

#include <string>
#include <vector>

#include "rt/core/scene.hpp"
#include "rt/render/render_loop.hpp"

namespace rt {

struct OffsetStudyRequest {
    std::vector<Real> scales{Real(1e-3), Real(1), Real(1e3), Real(1e5)};  // each times --scale
    std::string csv;                                                      // empty: no CSV
};

// Probes the CSV file, checks every scale, measures and prints; `epsilon` is the epsilon method's distance.
void run_offset_study(const Scene& scene, const OffsetStudyRequest& request, Real scale, Real epsilon,
                      const RenderSettings& settings);

}  // namespace rt
