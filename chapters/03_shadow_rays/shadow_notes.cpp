#include "shadow_notes.hpp"

#include "rt/core/formatted.hpp"
#include "shadow_render.hpp"

namespace rt {
std::vector<std::string> shadow_notes(const Scene& scene, const RayOffset& offset, Real scale,
                                      const RenderResult& result) {
    std::string method = "ray offset: " + std::string(to_string(offset.method));
    if (offset.method == OffsetMethod::kEpsilon) method += formatted(" (epsilon %g)", double(offset.epsilon));
    if (scale != 1) method += formatted(", scene scaled by %g", double(scale));
    const double camera_rays = double(result.rays[RayKind::kCamera]);
    std::vector<std::string> notes{
        method,
        formatted("%.0f point lights, %.3f shadow rays per camera ray", double(scene.point_lights.size()),
                  camera_rays > 0 ? double(result.rays[RayKind::kShadow]) / camera_rays : 0)};
    for (std::string& note : shading_notes(scene)) notes.push_back(std::move(note));
    return notes;
}

}  // namespace rt
