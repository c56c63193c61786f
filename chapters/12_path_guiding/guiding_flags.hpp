// The chapter's flags: the training and the guide's knobs, and the picture of what it learned at a point.
#pragma once

#include <CLI/CLI.hpp>

#include "guide_picture.hpp"
#include "guided_render.hpp"

namespace rt {

void add_guiding_flags(CLI::App& app, GuidedRenderOptions& guided, GuidePictureRequest& picture);

}  // namespace rt
