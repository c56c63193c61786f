// The flag of this chapter's quad-light sampling, which every later chapter that samples lights takes too:
// --quad-lights area|solid-angle (quad_light_strategy.hpp). Area is the default.
#pragma once

#include <CLI/CLI.hpp>

#include "quad_light_strategy.hpp"

namespace rt {

CLI::Option* add_quad_lights_flag(CLI::App& app, QuadLightSampling& strategy);

}  // namespace rt
