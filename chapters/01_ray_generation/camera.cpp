#include "camera.hpp"

#include <cmath>
#include <string>

#include "concentric_disk.hpp"
#include "rt/core/errors.hpp"

namespace rt {

PinholeCamera make_pinhole_camera(const CameraDesc& desc, int width, int height) {
    if (width <= 0 || height <= 0) {
        throw InputError("camera: image size must be positive, got " + std::to_string(width) + "x" +
                         std::to_string(height));
    }
    if (!(desc.vfov > 0 && desc.vfov < 180)) {
        throw InputError("camera.vfov: must be in (0, 180) degrees, got " + std::to_string(desc.vfov));
    }
    const Vec3d view = Vec3d(desc.at) - Vec3d(desc.from);
    if (glm::length(view) == 0) throw InputError("camera.at: must differ from camera.from");
    if (parallel(view, Vec3d(desc.up))) {
        throw InputError("camera.up: must not be parallel to the view direction (at - from)");
    }
    if (!(desc.aperture >= 0)) {
        throw InputError("camera.aperture: must be >= 0, got " + std::to_string(desc.aperture));
    }
    if (desc.focus_distance && !(*desc.focus_distance > 0)) {
        throw InputError("camera.focus_distance: must be > 0, got " + std::to_string(*desc.focus_distance));
    }
    const Vec3d w = glm::normalize(view);
    const Vec3d u_right_handed = glm::normalize(glm::cross(w, Vec3d(desc.up)));
    const Vec3d v = glm::cross(u_right_handed, w);
    const Vec3d u = desc.mirrored ? -u_right_handed : u_right_handed;
    const double half_height = std::tan(double(desc.vfov) * std::numbers::pi / 360.0);
    return PinholeCamera{desc.from,
                         Vec3(w),
                         Vec3(u),
                         Vec3(v),
                         Real(half_height * double(width) / double(height)),
                         Real(half_height),
                         width,
                         height,
                         desc.aperture,
                         desc.focus_distance.value_or(Real(glm::length(view)))};
}

Vec3 film_direction(const PinholeCamera& c, Real px, Real py) {
    const Real a = (Real(2) * px / Real(c.width) - Real(1)) * c.half_width;
    const Real b = (Real(1) - Real(2) * py / Real(c.height)) * c.half_height;
    return c.forward + a * c.right + b * c.up;
}

Ray camera_ray(const PinholeCamera& camera, Real px, Real py) {
    // EXERCISE(ch01.camera_ray) § The pinhole camera
    return Ray{camera.eye, glm::normalize(film_direction(camera, px, py))};
    // END EXERCISE
}

Ray thin_lens_ray(const PinholeCamera& camera, Real px, Real py, Vec2 u_lens) {
    const Vec2 lens = camera.lens_radius * sample_disk_concentric(u_lens);
    const Vec3 origin = camera.eye + lens.x * camera.right + lens.y * camera.up;
    const Vec3 focus = camera.eye + camera.focus_distance * film_direction(camera, px, py);
    return Ray{origin, glm::normalize(focus - origin)};
}

}  // namespace rt
