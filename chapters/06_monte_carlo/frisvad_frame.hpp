// The naive orthonormal basis, kept beside chapter 04's make_frame (Duff et al. 2017) for the lesson and the
// test that shows it failing. Frisvad (2012): a = 1 / (1 + n_z), c = −n_x n_y a,
// t = (1 − n_x² a, c, −n_x), b = (c, 1 − n_y² a, −n_y), with a special case only for n_z < −0.9999999.
// For n_z just above that threshold, 1 + n_z keeps a few bits at most and a = 1 / (1 + n_z) is huge: t and b
// lose their length and their right angles (Nelson Max 2017; Duff et al. 2017).
#pragma once

#include "04_direct_lighting/frame.hpp"

namespace rt {

inline Frame make_frame_frisvad(const Vec3& n) {
    if (n.z < Real(-0.9999999)) return Frame{{0, -1, 0}, {-1, 0, 0}, n};
    const Real a = Real(1) / (1 + n.z);
    const Real c = -n.x * n.y * a;
    return Frame{{1 - n.x * n.x * a, c, -n.x}, {c, 1 - n.y * n.y * a, -n.y}, n};
}

}  // namespace rt
