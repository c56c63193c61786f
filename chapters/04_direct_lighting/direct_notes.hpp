// What chapter 04's summary says about a render: how materials are shaded, the emitters not sampled as
// lights, the lights sampled and how, and the exact answer it is compared with on the analytic scene.
#pragma once

#include <string>
#include <vector>

#include "direct_lighting.hpp"

namespace rt {

std::vector<std::string> direct_notes(const MaterialTable& materials, const DirectLighting& shading,
                                      const DirectOptions& options, bool analytic);

}  // namespace rt
