#include "analytic_scene.hpp"

#include <array>
#include <numbers>
#include <variant>

#include "brdf.hpp"
#include "irradiance.hpp"

namespace rt {

std::optional<PlaneUnderQuad> find_plane_under_quad(const Scene& scene, const MaterialTable& materials) {
    if (scene.shapes.size() != 2 || scene.has_delta_lights() || scene.environment) return std::nullopt;
    const PlaneShape* plane = nullptr;
    const LambertBrdf* plane_brdf = nullptr;
    const Shape* lamp = nullptr;
    for (const Shape& shape : scene.shapes) {
        const Material& m = scene.material_of(shape);
        if (const auto* p = std::get_if<PlaneShape>(&shape.geometry); p && !m.emissive()) {
            plane_brdf = dynamic_cast<const LambertBrdf*>(&materials.bsdf(shape.material));
            if (!plane_brdf) return std::nullopt;
            plane = p;
        } else if (std::holds_alternative<QuadShape>(shape.geometry) && m.emissive()) {
            lamp = &shape;
        }
    }
    if (!plane || !lamp) return std::nullopt;
    const auto& q = std::get<QuadShape>(lamp->geometry);
    const QuadLight light = make_quad_light(q.origin, q.u, q.v, scene.material_of(*lamp).emission);
    if (!(light.area > 0)) return std::nullopt;
    const Vec3 n = glm::normalize(plane->normal);
    for (const Vec3& corner : {q.origin, q.origin + q.u, q.origin + q.v, q.origin + q.u + q.v}) {
        if (!(glm::dot(n, corner - plane->point) > 0)) return std::nullopt;
    }
    return PlaneUnderQuad{plane_brdf->albedo, light, lamp->material};
}

Color exact_radiance(const PlaneUnderQuad& analytic, const World& world, const Ray& ray) {
    const auto hit = world.intersect(ray);
    if (!hit) return Color(0);
    const QuadLight& q = analytic.light;
    if (hit->material == analytic.light_material) return hit->front_face ? q.radiance : Color(0);
    const Vec3d p(hit->point);
    // On the plane: the light emits toward p only if p is on its front side.
    if (!(glm::dot(Vec3d(q.normal), p - Vec3d(q.origin)) > 0)) return Color(0);
    const std::array<Vec3d, 4> corners{Vec3d(q.origin), Vec3d(q.origin) + Vec3d(q.u),
                                       Vec3d(q.origin) + Vec3d(q.u) + Vec3d(q.v),
                                       Vec3d(q.origin) + Vec3d(q.v)};
    const double e = polygon_irradiance(corners, p, Vec3d(hit->normal), 1.0);
    return Color(Vec3d(analytic.albedo) * Vec3d(q.radiance) * (e / std::numbers::pi));
}

Image exact_image(const PlaneUnderQuad& analytic, const World& world, const PinholeCamera& camera) {
    Image image(camera.width, camera.height);
    for (int y = 0; y < camera.height; ++y) {
        for (int x = 0; x < camera.width; ++x) {
            image.at(x, y) =
                exact_radiance(analytic, world, camera_ray(camera, Real(x) + Real(0.5), Real(y) + Real(0.5)));
        }
    }
    return image;
}

}  // namespace rt
