#include "scene_scale.hpp"

#include <cmath>
#include <cstdio>
#include <string>
#include <type_traits>
#include <variant>

#include "rt/errors.hpp"

namespace rt {

Scene scale_scene(const Scene& scene, Real s) {
    // Beyond 1e12 the scaled intensities (× s²) overflow float; below 1e-12 the squared distances underflow.
    if (!(s >= Real(1e-12) && s <= Real(1e12))) {
        char text[96];
        std::snprintf(text, sizeof text, "--scale: must be in [1e-12, 1e12], got %g", double(s));
        throw InputError(text);
    }
    Scene out = scene;
    out.camera.from *= s;
    out.camera.at *= s;
    for (PointLight& light : out.point_lights) {
        light.position *= s;
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
