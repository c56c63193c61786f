// Spawning a ray from a surface without hitting that surface again. The hit point is rounded: it lies up to
// hit.point_error off the true surface, on either side, so a ray started exactly there can meet its own
// surface at a tiny t > 0 (shadow acne). Three answers, kept side by side for the lesson:
//  - none:    o = p. Roughly half the rays leaving a surface re-hit it.
//  - epsilon: o = p + s ε n, s = sign(d · n): a fixed distance along the normal. Too small far from the
//             origin (p + ε n rounds back to p once ε < ulp(p)), too large for small scenes (rays start
//             beyond a nearby occluder: light leaks).
//  - robust:  o = p + s δ n with δ the largest distance along n between p and a point of its error box
//             (e = hit.point_error): it clears the box of possible true points; then each component rounded one ulp
//             further away from the surface (PBRT 4 §6.8.6): scale-free, and never short.
#pragma once

#include "02_intersection/hit.hpp"
#include "rt/core/enum_names.hpp"
#include "rt/core/math.hpp"
#include "rt/core/ray.hpp"

namespace rt {

enum class OffsetMethod { kNone, kEpsilon, kRobust };

struct RayOffset {
    OffsetMethod method = OffsetMethod::kRobust;
    Real epsilon = Real(1e-4);  // the fixed distance of OffsetMethod::kEpsilon
};

constexpr auto names_of(OffsetMethod) {
    return enum_names<OffsetMethod>(
        "--offset", {{OffsetMethod::kNone, "none"}, {OffsetMethod::kEpsilon, "epsilon"}, {OffsetMethod::kRobust, "robust"}});
}

// The offset of that method and epsilon; throws InputError unless epsilon is finite and > 0.
RayOffset make_ray_offset(OffsetMethod method, Real epsilon);

// The robust origin: o = p + s δ n (s = sign(d · n), +1 when d · n = 0; δ as above), then every component of
// o that moved is stepped one ulp further in the direction it moved (next_float.hpp).
Vec3 robust_offset(const Vec3& p, const Vec3& point_error, const Vec3& n, const Vec3& direction);
// The fixed-epsilon origin: o = p + s ε n, s = sign(d · n).
Vec3 epsilon_offset(const Vec3& p, const Vec3& n, const Vec3& direction, Real epsilon);

// The origin for a ray leaving the surface at `hit` toward `direction` (any length), on the side `direction`
// points to.
Vec3 offset_origin(const Hit& hit, const Vec3& direction, const RayOffset& offset);
// A ray leaving the surface at `hit` along the unit `direction`.
Ray spawn_ray(const Hit& hit, const Vec3& direction, const RayOffset& offset = {});

}  // namespace rt
