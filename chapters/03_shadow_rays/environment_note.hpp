// The note of a chapter that cannot sample an environment image (chapters 03 to 05): it shades the image as
// the constant sky of its average radiance over the sphere (EnvironmentLight::radiance), and says so.
#pragma once

#include <optional>
#include <string>

#include "rt/core/scene.hpp"

namespace rt {

// None for a constant environment, or none at all.
std::optional<std::string> environment_image_note(const std::optional<EnvironmentLight>& environment);

}  // namespace rt
