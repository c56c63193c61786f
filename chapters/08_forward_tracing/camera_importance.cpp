#include "camera_importance.hpp"

#include <algorithm>
#include <cmath>

namespace rt {

std::optional<FilmPoint> project_direction(const PinholeCamera& camera, const Vec3& d) {
    // EXERCISE(ch08.project_direction) § The measurement equation and the importance of a pinhole
    const Real z = glm::dot(d, camera.forward);
    const Real length = glm::length(d);
    if (!(z > 0) || !(length > 0)) return std::nullopt;
    const Real a = glm::dot(d, camera.right) / z;
    const Real b = glm::dot(d, camera.up) / z;
    const Real px = (a / camera.half_width + 1) * Real(camera.width) / 2;
    const Real py = (1 - b / camera.half_height) * Real(camera.height) / 2;
    if (!(px >= 0 && px < Real(camera.width) && py >= 0 && py < Real(camera.height))) return std::nullopt;
    FilmPoint p;
    p.px = px;
    p.py = py;
    p.cos_theta = std::min(Real(1), z / length);
    // px < W, yet ⌊px⌋ may round to W for px just below it in float: clamp to the last pixel.
    p.x = std::min(int(px), camera.width - 1);
    p.y = std::min(int(py), camera.height - 1);
    return p;
    // END EXERCISE
}

std::optional<FilmPoint> project_point(const PinholeCamera& camera, const Vec3& x) {
    return project_direction(camera, x - camera.eye);
}

Real pixel_area(const PinholeCamera& camera) {
    return 4 * camera.half_width * camera.half_height / (Real(camera.width) * Real(camera.height));
}

Real pinhole_importance(const PinholeCamera& camera, Real cos_theta) {
    // EXERCISE(ch08.pinhole_importance) § The measurement equation and the importance of a pinhole
    const Real c2 = cos_theta * cos_theta;
    return 1 / (pixel_area(camera) * c2 * c2);
    // END EXERCISE
}

PinholeCamera light_tracing_camera(const Scene& scene, int width, int height) {
    CameraDesc pinhole = scene.camera;
    pinhole.aperture = 0;
    return make_pinhole_camera(pinhole, width, height);
}

std::string lens_stand_in_note(const Scene& scene) {
    if (!(scene.camera.aperture > 0)) return "";
    return "camera.aperture: the light tracer's camera is the pinhole at the lens centre (no depth of field; "
           "--tracer reverse renders it)";
}

}  // namespace rt
