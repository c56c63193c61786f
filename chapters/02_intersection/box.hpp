// A box of the scene format: the axis-aligned box [min, max], transformed (scale, rotations, translation),
// becomes six quads. Chapter 02 intersects them; chapter 04 samples them when the box emits light.
#pragma once

#include <array>

#include "quad.hpp"
#include "rt/core/scene.hpp"

namespace rt {

// The 6 faces of a transformed box as quads (origin, u, v), each turned so u × v points outward.
std::array<Quad, 6> box_faces(const BoxShape& box);

}  // namespace rt
