#include "shadow_notes.hpp"

#include <cstdio>

#include "shadow_render.hpp"

namespace rt {
namespace {

std::string format(const char* pattern, double a, double b = 0) {
    char text[256];
    std::snprintf(text, sizeof text, pattern, a, b);
    return text;
}

}  // namespace

std::vector<std::string> shadow_notes(const Scene& scene, const RayOffset& offset, Real scale,
                                      const RenderResult& result) {
    std::string method = "ray offset: " + std::string(to_string(offset.method));
    if (offset.method == OffsetMethod::kEpsilon) method += format(" (epsilon %g)", double(offset.epsilon));
    if (scale != 1) method += format(", scene scaled by %g", double(scale));
    const double camera_rays = double(result.rays[RayKind::kCamera]);
    std::vector<std::string> notes{
        method,
        format("%.0f point lights, %.3f shadow rays per camera ray", double(scene.point_lights.size()),
               camera_rays > 0 ? double(result.rays[RayKind::kShadow]) / camera_rays : 0)};
    for (std::string& note : shading_notes(scene)) notes.push_back(std::move(note));
    return notes;
}

}  // namespace rt
