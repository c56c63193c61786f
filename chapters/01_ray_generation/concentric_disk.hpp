// Uniform points on the unit disk from uniform points of the square, by Shirley and Chiu's concentric map
// ("A Low Distortion Map Between Disk and Square", 1997), as pbrt-v4's SampleUniformDiskConcentric. The
// square [−1, 1]² is cut into four triangles by its diagonals; each is mapped onto a quarter of the disk, its
// concentric squares onto concentric circles:
//   (a, b) = 2 u − 1;   |a| > |b|:  r = a,  φ = (π/4) (b / a);   otherwise:  r = b,  φ = π/2 − (π/4) (a / b)
//   p = r (cos φ, sin φ)
// Area is preserved (the Jacobian is constant, π / 4 of the square's), so p is uniform on the disk, density
// 1 / π. Unlike the polar map (r = √u₁, φ = 2π u₂), neighbouring points of the square stay neighbours with
// little stretching: stratified (u₁, u₂) stay stratified on the lens.
#pragma once

#include "rt/core/math.hpp"

namespace rt {

Vec2 sample_disk_concentric(Vec2 u);

}  // namespace rt
