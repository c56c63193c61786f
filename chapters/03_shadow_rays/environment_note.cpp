#include "environment_note.hpp"

#include "rt/core/formatted.hpp"

namespace rt {

std::optional<std::string> environment_image_note(const std::optional<EnvironmentLight>& environment) {
    if (!environment || !environment->image) return std::nullopt;
    const Color& c = environment->radiance;
    return "environment image " + environment->image_file +
           ": sampled by importance from chapter 06 on; shaded here as a constant sky of its average radiance " +
           formatted("(%.4g, %.4g, %.4g)", c.r, c.g, c.b);
}

}  // namespace rt
