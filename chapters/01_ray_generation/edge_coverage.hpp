// A case whose exact answer is known, to measure anti-aliasing: a straight edge through the film. The
// half-space {d : n · d > 0} of ray directions (a plane through the eye) is, on the film, the half-plane
// c + a·px + b·py > 0, because film_direction is linear in (px, py). The exact fraction of each pixel it
// covers is an area we can compute, so every sampler's error can be measured exactly.
#pragma once

#include "camera.hpp"

namespace rt {

struct FilmEdge {
    Vec3 normal;  // a ray direction d is "inside" when normal · d > 0
    double c, a, b;  // the same half-plane on the film: c + a·px + b·py > 0 (in double)
};

// The edge through the film's centre, turned `tilt_degrees` from the vertical.
FilmEdge make_film_edge(const PinholeCamera& camera, Real tilt_degrees);

bool inside(const FilmEdge& edge, const Vec3& direction);

// The exact area of pixel [x, x+1] × [y, y+1] inside the half-plane: the unit square clipped by the line
// (one Sutherland–Hodgman step), then the shoelace formula.
double exact_coverage(const FilmEdge& edge, int x, int y);

}  // namespace rt
