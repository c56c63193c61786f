#include "triangle.hpp"

#include <algorithm>
#include <cmath>

#include "float_error.hpp"

namespace rt {

// Computed with no branch: the axes are chosen by arithmetic on the comparisons and the components read from
// an array, since the choice changes from one incoherent ray to the next and a branch on it is often
// mispredicted (glm's d[k] with k known only at run time is a switch, a branch too).
WatertightRay make_watertight_ray(const Ray& ray) {
    const Vec3& d = ray.direction;
    const Vec3 a = abs(d);
    const Real component[3] = {d.x, d.y, d.z};
    // kz = 0 when |d_x| is largest, else 1 when |d_y| is, else 2 (of equal magnitudes, the later axis).
    const int x_largest = int(a.x > a.y) & int(a.x > a.z);
    const int y_largest = int(!(a.x > a.y)) & int(a.y > a.z);
    const int kz = 2 - 2 * x_largest - y_largest;
    // (kx, ky) = (kz + 1, kz + 2) mod 3, swapped when d_kz < 0 to keep the winding.
    const int swapped = int(component[kz] < 0);
    const int kx = (kz + 1 + swapped) % 3, ky = (kz + 2 - swapped) % 3;
    return {kx, ky, kz, component[kx] / component[kz], component[ky] / component[kz], Real(1) / component[kz]};
}

std::optional<TriangleHit> intersect_triangle_watertight(const Ray& ray, const WatertightRay& s,
                                                         const Triangle& triangle, Real t_max) {
    // EXERCISE(ch02.triangle_watertight) § Each shape's equation
    // Translate: the vertices relative to the ray's origin.
    const Vec3 a = triangle.p0 - ray.origin;
    const Vec3 b = triangle.p1 - ray.origin;
    const Vec3 c = triangle.p2 - ray.origin;
    // Permute and shear: the ray becomes the +z axis; (x, y) is where each vertex lies around it.
    const Real ax = a[s.kx] - s.sx * a[s.kz], ay = a[s.ky] - s.sy * a[s.kz];
    const Real bx = b[s.kx] - s.sx * b[s.kz], by = b[s.ky] - s.sy * b[s.kz];
    const Real cx = c[s.kx] - s.sx * c[s.kz], cy = c[s.ky] - s.sy * c[s.kz];
    // Edge functions: twice the signed area of the triangle (0, vertex, vertex) opposite each vertex.
    Real u = cx * by - cy * bx;
    Real v = ax * cy - ay * cx;
    Real w = bx * ay - by * ax;
    // Exactly zero in float may be rounding: decide the sign in double, where products of floats are exact.
    if (u == 0 || v == 0 || w == 0) {
        u = Real(double(cx) * double(by) - double(cy) * double(bx));
        v = Real(double(ax) * double(cy) - double(ay) * double(cx));
        w = Real(double(bx) * double(ay) - double(by) * double(ax));
    }
    if ((u < 0 || v < 0 || w < 0) && (u > 0 || v > 0 || w > 0)) return std::nullopt;
    const Real det = u + v + w;
    if (det == 0) return std::nullopt;  // the ray lies in the triangle's plane, or the triangle is degenerate
    // The scaled distance T = det · t, tested against (0, t_max) before dividing.
    const Real az = s.sz * a[s.kz], bz = s.sz * b[s.kz], cz = s.sz * c[s.kz];
    const Real t_scaled = u * az + v * bz + w * cz;
    if (std::abs(t_scaled) < kSmallestScaledDistance) {  // rounded among subnormals, perhaps: in double
        return watertight_hit_in_double({u, v, w}, {ax, bx, cx}, {ay, by, cy}, {az, bz, cz}, t_max);
    }
    if (det < 0 ? (t_scaled >= 0 || t_scaled < t_max * det) : (t_scaled <= 0 || t_scaled > t_max * det)) {
        return std::nullopt;
    }
    const Real inverse = Real(1) / det;
    const Real t = t_scaled * inverse;
    // t itself is rounded: a ray leaving the triangle's own surface can compute a tiny t > 0 for it. Accept t
    // only beyond the bound δt on its rounding error (PBRT 4 §6.8.7), from the largest sheared coordinates.
    const Real max_z = std::max({std::abs(az), std::abs(bz), std::abs(cz)});
    const Real max_x = std::max({std::abs(ax), std::abs(bx), std::abs(cx)});
    const Real max_y = std::max({std::abs(ay), std::abs(by), std::abs(cy)});
    const Real max_e = std::max({std::abs(u), std::abs(v), std::abs(w)});
    const Real delta_t = watertight_distance_bound(max_x, max_y, max_z, max_e, std::abs(inverse));
    if (!(t > delta_t && t < t_max)) return std::nullopt;
    return TriangleHit{t, {v * inverse, w * inverse}};
    // END EXERCISE
}

std::optional<TriangleHit> watertight_hit_in_double(const Vec3& edge, const Vec3& x, const Vec3& y,
                                                    const Vec3& z, Real t_max) {
    // det as the float test sums it: the same sign and the same barycentrics.
    const Real det = edge.x + edge.y + edge.z;
    if (det == 0) return std::nullopt;
    const Vec3d e(edge), z_d(z);
    // t = T / det, each product exact, the sum and the quotient rounded once.
    const double t = glm::dot(e, z_d) / double(det);
    auto largest = [](const Vec3& v) {
        return double(std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}));
    };
    const double delta_t = watertight_distance_bound(largest(x), largest(y), largest(z), largest(edge),
                                                     std::abs(1 / double(det)));
    if (!(t > delta_t && Real(t) < t_max)) return std::nullopt;
    const Real inverse = Real(1) / det;
    return TriangleHit{Real(t), {edge.y * inverse, edge.z * inverse}};
}

std::optional<TriangleHit> intersect_triangle_moller(const Ray& ray, const Triangle& triangle, Real t_max) {
    // EXERCISE(ch02.triangle_moller) § Each shape's equation
    const Vec3 e1 = triangle.p1 - triangle.p0;
    const Vec3 e2 = triangle.p2 - triangle.p0;
    const Vec3 p = glm::cross(ray.direction, e2);
    const Real det = glm::dot(e1, p);
    if (det == 0) return std::nullopt;
    const Real inverse = Real(1) / det;
    const Vec3 s = ray.origin - triangle.p0;
    const Real b1 = glm::dot(s, p) * inverse;
    if (!(b1 >= 0 && b1 <= 1)) return std::nullopt;
    const Vec3 q = glm::cross(s, e1);
    const Real b2 = glm::dot(ray.direction, q) * inverse;
    if (!(b2 >= 0 && b1 + b2 <= 1)) return std::nullopt;
    const Real t = glm::dot(e2, q) * inverse;
    if (!(t > 0 && t < t_max)) return std::nullopt;
    return TriangleHit{t, {b1, b2}};
    // END EXERCISE
}

std::optional<TriangleHit> intersect_triangle(const Ray& ray, const Triangle& triangle, Real t_max,
                                              TriangleTest test) {
    if (test == TriangleTest::kMollerTrumbore) return intersect_triangle_moller(ray, triangle, t_max);
    return intersect_triangle_watertight(ray, make_watertight_ray(ray), triangle, t_max);
}

Vec3 triangle_normal(const Triangle& triangle) {
    const Vec3 n = glm::cross(triangle.p1 - triangle.p0, triangle.p2 - triangle.p0);
    const Real length = glm::length(n);
    return length > 0 ? n / length : Vec3{0, 0, 1};
}

}  // namespace rt
