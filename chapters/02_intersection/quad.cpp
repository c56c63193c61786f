#include "quad.hpp"

namespace rt {

Quad make_quad(const Vec3& origin, const Vec3& u, const Vec3& v) {
    const Vec3 n = glm::cross(u, v);
    const Real n2 = glm::dot(n, n);
    if (!(n2 > 0)) return {origin, u, v, Vec3{0, 0, 1}, Vec3{0}, Vec3{0}};  // degenerate: zero axes mark it
    const Vec3 w = n / n2;
    return {origin, u, v, n / std::sqrt(n2), glm::cross(v, w), glm::cross(w, u)};
}

}  // namespace rt
