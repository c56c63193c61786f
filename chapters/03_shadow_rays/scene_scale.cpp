#include "scene_scale.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <type_traits>
#include <variant>

#include "rt/core/errors.hpp"
#include "rt/io/scene_loader.hpp"

namespace rt {

void for_each_shape_extent(const Scene& scene, const std::function<void(const Vec3&)>& take) {
    for (const Shape& shape : scene.shapes) {
        std::visit(
            [&](const auto& g) {
                using T = std::decay_t<decltype(g)>;
                if constexpr (std::is_same_v<T, SphereShape>) {
                    take(g.center - Vec3(g.radius));
                    take(g.center + Vec3(g.radius));
                } else if constexpr (std::is_same_v<T, QuadShape>) {
                    for (const Vec3& p : {g.origin, g.origin + g.u, g.origin + g.v, g.origin + g.u + g.v})
                        take(p);
                } else if constexpr (std::is_same_v<T, TriangleShape>) {
                    for (const Vec3& v : g.vertices) take(v);
                } else if constexpr (std::is_same_v<T, PlaneShape>) {
                    take(g.point);
                } else if constexpr (std::is_same_v<T, BoxShape>) {
                    for (int corner = 0; corner < 8; ++corner) {
                        take(g.transform.apply_to_point({corner & 1 ? g.max.x : g.min.x,
                                                         corner & 2 ? g.max.y : g.min.y,
                                                         corner & 4 ? g.max.z : g.min.z}));
                    }
                } else if constexpr (std::is_same_v<T, MeshShape>) {
                    for (const Vec3& p : g.positions) take(p);
                }
            },
            shape.geometry);
    }
}

double largest_coordinate(const Scene& scene) {
    double largest = 0;
    const auto take = [&](const Vec3& p) {
        for (int i = 0; i < 3; ++i) largest = std::max(largest, std::abs(double(p[i])));
    };
    take(scene.camera.from);
    take(scene.camera.at);
    for (const PointLight& light : scene.point_lights) take(light.position);
    for (const SpotLight& light : scene.spot_lights) {
        take(light.position);
        take(light.at);
    }
    for_each_shape_extent(scene, take);
    return largest;
}

void check_scale(const Scene& scene, Real s, const std::string& flag) {
    char text[256];
    // Beyond 1e12 the scaled intensities (× s²) overflow float; below 1e-12 the squared distances underflow.
    if (!(s >= Real(1e-12) && s <= Real(1e12))) {
        std::snprintf(text, sizeof text, "%s: must be in [1e-12, 1e12], got %g", flag.c_str(), double(s));
        throw InputError(text);
    }
    const double largest = largest_coordinate(scene);
    if (largest * double(s) > kLargestSceneNumber) {
        std::snprintf(
            text, sizeof text,
            "%s: %g moves the scene's farthest coordinate (%g) to %g, beyond a scene's limit of %g: "
            "give a scale of at most %g",
            flag.c_str(), double(s), largest, largest * double(s), kLargestSceneNumber,
            kLargestSceneNumber / largest);
        throw InputError(text);
    }
}

Scene scale_scene(const Scene& scene, Real s) {
    check_scale(scene, s);
    Scene out = scene;
    out.camera.from *= s;
    out.camera.at *= s;
    for (PointLight& light : out.point_lights) {
        light.position *= s;
        light.intensity *= s * s;
    }
    for (SpotLight& light : out.spot_lights) {
        light.position *= s;
        light.at *= s;
        light.intensity *= s * s;
    }
    for (Shape& shape : out.shapes) {
        std::visit(
            [&](auto& g) {
                using T = std::decay_t<decltype(g)>;
                if constexpr (std::is_same_v<T, SphereShape>) {
                    g.center *= s;
                    g.radius *= s;
                } else if constexpr (std::is_same_v<T, QuadShape>) {
                    g.origin *= s;
                    g.u *= s;
                    g.v *= s;
                } else if constexpr (std::is_same_v<T, TriangleShape>) {
                    for (Vec3& v : g.vertices) v *= s;
                } else if constexpr (std::is_same_v<T, PlaneShape>) {
                    g.point *= s;
                } else if constexpr (std::is_same_v<T, BoxShape>) {
                    // s (R (S p) + t) = R ((s S) p) + s t: scale the transform's scale and translation.
                    g.transform.scale *= s;
                    g.transform.translate *= s;
                } else if constexpr (std::is_same_v<T, MeshShape>) {
                    for (Vec3& p : g.positions) p *= s;
                }
            },
            shape.geometry);
    }
    return out;
}

}  // namespace rt
