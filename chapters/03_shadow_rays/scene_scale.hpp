// The same scene at another size: every length multiplied by s (about the origin), so its coordinates reach
// s times as far, and every point light's intensity by s², so that E = I cos θ / r² — and the picture — stay
// the same (a spot light's too; a distant light's irradiance does not depend on distance). Only the
// floating-point numbers change: what an offset does at 1e-3 and at 1e5 can be compared.
#pragma once

#include <functional>
#include <string>

#include "rt/core/scene.hpp"

namespace rt {

// Calls take(p) for points whose bounding box holds every shape: a sphere's lowest and highest corners, a
// quad's, a triangle's and a box's corners (after its transform), a mesh's vertices, a plane's point.
void for_each_shape_extent(const Scene& scene, const std::function<void(const Vec3&)>& take);

// The largest magnitude of any coordinate of the scene's camera, point and spot lights and shapes (their
// extent points above).
double largest_coordinate(const Scene& scene);

// Throws InputError unless s is in [1e-12, 1e12] (intensities × s² stay finite in float) and the scaled
// scene's coordinates stay within a scene file's limit (kLargestSceneNumber): beyond it ray tests overflow
// float, and the picture turns black. `flag` names where s came from in the message.
void check_scale(const Scene& scene, Real s, const std::string& flag = "--scale");

// The scene scaled by s; check_scale's refusals first.
Scene scale_scene(const Scene& scene, Real s);

}  // namespace rt
