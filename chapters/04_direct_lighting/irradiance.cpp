#include "irradiance.hpp"

#include <cmath>
#include <numbers>
#include <vector>

namespace rt {
namespace {

// Sutherland–Hodgman against one plane: keeps the part of the polygon where n · (x − p) >= 0.
std::vector<Vec3d> clip_to_horizon(std::span<const Vec3d> polygon, const Vec3d& p, const Vec3d& n) {
    std::vector<Vec3d> out;
    const std::size_t k = polygon.size();
    for (std::size_t i = 0; i < k; ++i) {
        const Vec3d& a = polygon[i];
        const Vec3d& b = polygon[(i + 1) % k];
        const double ha = glm::dot(n, a - p), hb = glm::dot(n, b - p);
        if (ha >= 0) out.push_back(a);
        if ((ha >= 0) != (hb >= 0)) out.push_back(a + (b - a) * (ha / (ha - hb)));
    }
    return out;
}

}  // namespace

double polygon_irradiance(std::span<const Vec3d> vertices, const Vec3d& p, const Vec3d& n, double radiance) {
    // EXERCISE(ch04.lambert_polygon) § Exact answers
    const std::vector<Vec3d> polygon = clip_to_horizon(vertices, p, n);
    double sum = 0;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const Vec3d a = polygon[i] - p;
        const Vec3d b = polygon[(i + 1) % polygon.size()] - p;
        const Vec3d cross = glm::cross(a, b);
        const double length = glm::length(cross);
        if (length == 0) continue;  // an edge through p, or of zero length: it subtends no angle
        const double theta = std::atan2(length, glm::dot(a, b));  // accurate for small and large angles
        sum += theta * glm::dot(n, cross / length);
    }
    return radiance / 2 * std::abs(sum);
    // END EXERCISE
}

double sphere_irradiance(double radiance, double radius, double distance, double cos_theta) {
    const double ratio = radius / distance;
    return std::numbers::pi * radiance * ratio * ratio * cos_theta;
}

double coaxial_disc_irradiance(double radiance, double radius, double height) {
    return std::numbers::pi * radiance * radius * radius / (radius * radius + height * height);
}

double sky_irradiance(double radiance) {
    return std::numbers::pi * radiance;
}

}  // namespace rt
