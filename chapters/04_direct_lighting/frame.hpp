// An orthonormal frame (t, b, n) around a unit normal n, for moving directions between the world and a
// local frame where n is +z. Built without branches on n's direction, so it is stable for every unit n.
#pragma once

#include <cmath>

#include "rt/core/math.hpp"

namespace rt {

struct Frame {
    Vec3 t;
    Vec3 b;
    Vec3 n;

    // Local (x, y, z) to world: x t + y b + z n.
    Vec3 to_world(const Vec3& local) const { return local.x * t + local.y * b + local.z * n; }
    // World to local: (v · t, v · b, v · n).
    Vec3 to_local(const Vec3& v) const { return {glm::dot(v, t), glm::dot(v, b), glm::dot(v, n)}; }
};

// Duff et al. 2017 ("Building an orthonormal basis, revisited"): with s = sign(n_z), a = −1 / (s + n_z),
// c = n_x n_y a: t = (1 + s n_x² a, s c, −s n_x), b = (c, s + n_y² a, −n_y). No division by a small number:
// s + n_z has magnitude at least 1.
inline Frame make_frame(const Vec3& n) {
    const Real s = std::copysign(Real(1), n.z);
    const Real a = Real(-1) / (s + n.z);
    const Real c = n.x * n.y * a;
    return Frame{{1 + s * n.x * n.x * a, s * c, -s * n.x}, {c, s + n.y * n.y * a, -n.y}, n};
}

}  // namespace rt
