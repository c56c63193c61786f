// libFuzzer target for chapter 02's BVH: the bytes are a soup of floats (any bit pattern but NaN and
// infinity: subnormal, zero of either sign, 1e-40 beside 1e38), read as boxes and as triangles, and rays.
// The BVH over the boxes (each hit at its exact entry distance) must return exactly the brute-force nearest
// for every ray, whatever its direction; the world over the triangles must find the brute-force nearest hit
// within its rounding (bvh_agreement.hpp) for every ray of unit direction. A fault in the build or the
// traversal, a sanitizer report or a disagreement stops the fuzzer.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "02_intersection/bvh_agreement.hpp"

namespace {

// The input's floats in order, the non-finite ones left out.
std::vector<float> floats_of(const std::uint8_t* data, std::size_t size) {
    std::vector<float> out;
    for (std::size_t i = 0; i + 4 <= size; i += 4) {
        float x;
        std::memcpy(&x, data + i, 4);
        if (std::isfinite(x)) out.push_back(x);
    }
    return out;
}

void fail(const std::string& what) {
    std::fprintf(stderr, "bvh_fuzz: %s\n", what.c_str());
    std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::vector<float> f = floats_of(data, size);
    if (f.size() < 12) return 0;
    // The first quarter are rays (origin, direction, t_max: 7 floats each), the rest the soup.
    const std::size_t ray_floats = (f.size() / 4) / 7 * 7;
    std::vector<rt::BvhQuery> queries;
    for (std::size_t i = 0; i + 7 <= ray_floats; i += 7) {
        const rt::Vec3 d{f[i + 3], f[i + 4], f[i + 5]};
        if (d == rt::Vec3(0)) continue;
        queries.push_back({rt::Ray{{f[i], f[i + 1], f[i + 2]}, d}, f[i + 6] > 0 ? f[i + 6] : rt::kInfinity});
    }
    if (queries.empty()) return 0;
    std::vector<rt::Vec3> points;
    for (std::size_t i = ray_floats; i + 3 <= f.size(); i += 3) points.push_back({f[i], f[i + 1], f[i + 2]});
    std::vector<rt::Aabb> boxes;
    for (std::size_t i = 0; i + 2 <= points.size(); i += 2) {
        rt::Aabb b;
        b.extend(points[i]);
        b.extend(points[i + 1]);
        boxes.push_back(b);
    }
    if (!boxes.empty()) {
        if (const auto disagreement = rt::first_box_disagreement(boxes, queries))
            fail("boxes: " + *disagreement);
    }
    // The triangle tests are exact only where float's products neither overflow nor underflow: the soup's
    // triangles are kept within 1e-15 to 1e15 in magnitude (or zero), as the scene loader's 1e9 keeps them.
    // The rays' origins are kept to the same range: an origin 1e-40 from a triangle meets it at t = 1e-40,
    // where the same products underflow (the fuzzer found the BVH and brute force disagreeing there).
    auto in_range = [](const rt::Vec3& p) {
        bool usable = true;
        for (int i = 0; i < 3; ++i)
            usable = usable && (p[i] == 0 || (std::abs(p[i]) > 1e-15f && std::abs(p[i]) < 1e15f));
        return usable;
    };
    std::vector<rt::Vec3> corners;
    for (const rt::Vec3& p : points) {
        if (in_range(p)) corners.push_back(p);
    }
    // The world's rays have unit directions (its hits' distances and error bounds assume it): normalised in
    // double, where no component's square underflows or overflows.
    std::vector<rt::BvhQuery> unit_queries;
    for (const rt::BvhQuery& q : queries) {
        if (!in_range(q.ray.origin)) continue;
        const rt::Vec3d d(q.ray.direction);
        const double length = glm::length(d);
        if (!(length > 0) || !std::isfinite(length)) continue;
        const rt::Vec3 unit(d / length);
        // And so are the unit directions' components: 2.9e-39 beside −1 makes the slab and shear products
        // underflow, and the fuzzer found the BVH missing a hit there (a limit of chapter 02 its lesson
        // names).
        if (!in_range(unit)) continue;
        unit_queries.push_back({rt::Ray{q.ray.origin, unit}, q.t_max});
    }
    if (corners.size() >= 3 && !unit_queries.empty()) {
        if (const auto disagreement = rt::first_bvh_disagreement(rt::triangle_soup(corners), unit_queries)) {
            fail("triangles: " + *disagreement);
        }
    }
    return 0;
}
