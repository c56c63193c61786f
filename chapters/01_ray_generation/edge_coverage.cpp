#include "edge_coverage.hpp"

#include <array>
#include <cmath>

namespace rt {

FilmEdge make_film_edge(const PinholeCamera& camera, Real tilt_degrees) {
    const Real tilt = radians(tilt_degrees);
    // A normal perpendicular to the view direction: the plane passes through the eye and the film's centre.
    const Vec3 normal = std::cos(tilt) * camera.right + std::sin(tilt) * camera.up;
    // n · d(px, py) = n·w + (2px/W − 1)·hw·(n·u) + (1 − 2py/H)·hh·(n·v), expanded in double.
    const Vec3d n(normal);
    const double nw = glm::dot(n, Vec3d(camera.forward));
    const double nu = glm::dot(n, Vec3d(camera.right)) * double(camera.half_width);
    const double nv = glm::dot(n, Vec3d(camera.up)) * double(camera.half_height);
    return FilmEdge{normal, nw - nu + nv, 2.0 * nu / camera.width, -2.0 * nv / camera.height};
}

bool inside(const FilmEdge& edge, const Vec3& direction) { return glm::dot(edge.normal, direction) > 0; }

double exact_coverage(const FilmEdge& edge, int x, int y) {
    const std::array<glm::dvec2, 4> square = {glm::dvec2(x, y), glm::dvec2(x + 1, y), glm::dvec2(x + 1, y + 1),
                                              glm::dvec2(x, y + 1)};
    auto value = [&](const glm::dvec2& p) { return edge.c + edge.a * p.x + edge.b * p.y; };
    std::array<glm::dvec2, 5> clipped{};  // a square cut by a line has at most 5 corners
    int count = 0;
    for (std::size_t i = 0; i < square.size(); ++i) {
        const glm::dvec2& p = square[i];
        const glm::dvec2& q = square[(i + 1) % square.size()];
        const double vp = value(p), vq = value(q);
        if (vp > 0) clipped[std::size_t(count++)] = p;
        if ((vp > 0) != (vq > 0)) clipped[std::size_t(count++)] = p + (q - p) * (vp / (vp - vq));
    }
    double twice_area = 0;  // shoelace: ½ Σ (xᵢ yᵢ₊₁ − xᵢ₊₁ yᵢ)
    for (int i = 0; i < count; ++i) {
        const glm::dvec2& p = clipped[std::size_t(i)];
        const glm::dvec2& q = clipped[std::size_t((i + 1) % count)];
        twice_area += p.x * q.y - q.x * p.y;
    }
    return std::abs(twice_area) / 2;
}

}  // namespace rt
