#include "rt/core/scene.hpp"

#include <cmath>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

namespace rt {

Vec3 Transform::apply_to_point(const Vec3& p) const {
    if (matrix) return Vec3(*matrix * glm::dvec4(Vec3d(p), 1.0));
    return rotate(p * scale) + translate;
}

Vec3 Transform::apply_to_normal(const Vec3& n) const {
    if (matrix) return Vec3(glm::transpose(glm::inverse(glm::dmat3(*matrix))) * Vec3d(n));
    return rotate(n / scale);
}

bool Transform::mirrors() const {
    if (matrix) return glm::determinant(glm::dmat3(*matrix)) < 0;
    return (scale.x < 0) != ((scale.y < 0) != (scale.z < 0));
}

Vec3 Transform::rotate(Vec3 q) const {
    const Vec3 r = rotate_degrees * (kPi / Real(180));
    // Rotation about x, then y, then z (right-handed, counter-clockwise looking down the axis).
    q = {q.x, std::cos(r.x) * q.y - std::sin(r.x) * q.z, std::sin(r.x) * q.y + std::cos(r.x) * q.z};
    q = {std::cos(r.y) * q.x + std::sin(r.y) * q.z, q.y, -std::sin(r.y) * q.x + std::cos(r.y) * q.z};
    return {std::cos(r.z) * q.x - std::sin(r.z) * q.y, std::sin(r.z) * q.x + std::cos(r.z) * q.y, q.z};
}

bool Scene::has_area_lights() const {
    for (const Shape& s : shapes) {
        if (material_of(s).emissive()) return true;
    }
    return false;
}

bool Scene::has_delta_lights() const {
    return !point_lights.empty() || !distant_lights.empty() || !spot_lights.empty();
}

bool Scene::has_lights() const {
    return has_delta_lights() || environment || has_area_lights();
}

std::vector<bool> Scene::used_materials() const {
    std::vector<bool> used(materials.size(), false);
    for (const Shape& s : shapes) used[std::size_t(s.material)] = true;
    return used;
}

}  // namespace rt
