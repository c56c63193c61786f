// `--shadow-study` as chapter 04's executable runs it: on a plane under one quad light (the scene given, when
// it is one, else the course's analytic scene at the run's image size), RMSE to the exact image and time for
// 1 to 256 shadow samples per pixel with both light samplers; the table on stdout and, when asked, as CSV.
#pragma once

#include <string>

#include "direct_lighting.hpp"
#include "rt/core/scene.hpp"
#include "rt/render/render_loop.hpp"

namespace rt {

void run_shadow_study(const Scene& given, const DirectOptions& options, const RenderSettings& settings,
                      const std::string& csv);

}  // namespace rt
