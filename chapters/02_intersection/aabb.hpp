// Axis-aligned bounding boxes and the slab test. A box is the intersection of three slabs
// min_i <= x_i <= max_i; the ray o + t d is inside slab i for t between (min_i − o_i) / d_i and
// (max_i − o_i) / d_i, and inside the box for t in the intersection of the three intervals.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "float_error.hpp"
#include "rt/core/math.hpp"
#include "rt/core/ray.hpp"

namespace rt {

struct Aabb {
    Vec3 min{kInfinity};
    Vec3 max{-kInfinity};  // empty until a point is added

    void extend(const Vec3& p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    void extend(const Aabb& b) {
        min = glm::min(min, b.min);
        max = glm::max(max, b.max);
    }
    Vec3 center() const { return (min + max) * Real(0.5); }
    // Whether p lies in the box, faces included (one test per face, no branch).
    bool contains(const Vec3& p) const {
        return (min.x <= p.x) & (p.x <= max.x) & (min.y <= p.y) & (p.y <= max.y) & (min.z <= p.z) & (p.z <= max.z);
    }
    // Half the surface area, 2 (xy + yz + zx) / 2: only ratios of areas matter to the SAH.
    Real half_area() const {
        const Vec3 e = glm::max(max - min, Vec3{0});
        return e.x * e.y + e.y * e.z + e.z * e.x;
    }
    int longest_axis() const {
        const Vec3 e = max - min;
        return e.x > e.y ? (e.x > e.z ? 0 : 2) : (e.y > e.z ? 1 : 2);
    }
};

// 1 / d per component, computed once per ray: d_i = +0 gives +∞ and d_i = −0 gives −∞ (a subnormal d_i
// gives ±∞ too: slab_entry tells them apart by d_i itself).
inline Vec3 inverse_direction(const Vec3& d) {
    return Vec3{1} / d;
}

// Widens a slab's computed entry t_near and exit t_far by the bound on their rounding (in units of γₙ,
// float_error.hpp; PBRT 4 §6.8, derived in the lesson) and by what rounding does below float's normal range
// (there a product is rounded to a multiple of the smallest float, not to a relative error), so that the
// exact interval lies inside the widened one. T is a Real or a SIMD register of them (wide_bvh.hpp).
template <typename T>
void widen_slab(T& t_near, T& t_far) {
    // EXERCISE(ch02.slab_widening) § Bounding boxes and the BVH
    constexpr Real kGamma3 = gamma_bound(3);
    constexpr Real kSmallest = std::numeric_limits<Real>::denorm_min();
    t_near = t_near * (1 - 2 * kGamma3) - kSmallest;
    t_far = t_far * (1 + 2 * kGamma3) + kSmallest;
    // END EXERCISE
}

// The slab test on [0, t_max]: the entry distance into the box, or +∞ when the ray misses it.
// A direction component d_i = ±0 never reaches 1 / d_i: the ray is parallel to slab i and stays inside it
// (min_i <= o_i <= max_i, faces included) or outside it for ever, whatever the zero's sign. A subnormal d_i
// (below 1.2e-38) has an infinite 1 / d_i in float: its slab is computed in double, where the quotient is
// finite. A ray starting inside the box enters at t = 0. Each slab's entry and exit are widened
// (widen_slab), so rounding never culls a surface lying on the box, neither against the exit nor against a
// t_max that is the rounded distance of a hit on the same plane; a box of zero thickness (min_i = max_i) is
// entered and left at one t.
inline Real slab_entry(const Aabb& box, const Ray& ray, const Vec3& inverse_d, Real t_max) {
    // EXERCISE(ch02.slab_test) § Bounding boxes and the BVH
    Real t_enter = 0;
    Real t_exit = t_max;
    for (int i = 0; i < 3; ++i) {
        Real t_near, t_far;
        if (std::abs(inverse_d[i]) < kInfinity) {
            t_near = (box.min[i] - ray.origin[i]) * inverse_d[i];
            t_far = (box.max[i] - ray.origin[i]) * inverse_d[i];
        } else if (ray.direction[i] == 0) {
            if (ray.origin[i] < box.min[i] || ray.origin[i] > box.max[i]) return kInfinity;
            continue;
        } else {
            const double d = ray.direction[i];
            t_near = Real((double(box.min[i]) - double(ray.origin[i])) / d);
            t_far = Real((double(box.max[i]) - double(ray.origin[i])) / d);
        }
        if (t_near > t_far) std::swap(t_near, t_far);
        widen_slab(t_near, t_far);
        t_enter = std::max(t_enter, t_near);
        t_exit = std::min(t_exit, t_far);
    }
    return t_enter <= t_exit ? t_enter : kInfinity;
    // END EXERCISE
}

// Whether the ray meets the box for some t in [0, t_max].
inline bool hits_box(const Aabb& box, const Ray& ray, Real t_max) {
    return slab_entry(box, ray, inverse_direction(ray.direction), t_max) < kInfinity;
}

}  // namespace rt
