// What other code may watch along a path, without changing it: a PathObserver handed to the path loop is told
// what happens at each step, and may end the path at a vertex. The loop draws the same random numbers with
// or without one; without one (null, the default) each hook costs a pointer check. The code that needs a
// hook owns its observer class: this file defines only the interface. (A study of how L grows derives its own
// PathState instead: path_tracer.hpp.)
#pragma once

#include "02_intersection/hit.hpp"
#include "04_direct_lighting/bsdf.hpp"
#include "rt/core/math.hpp"

namespace rt {

class PathObserver {
  public:
    virtual ~PathObserver() = default;
    // The path reached a surface vertex `hit` that scatters with `flags`, after `bounces` non-delta bounces.
    // false ends the path there.
    virtual bool reached(const Hit& /*hit*/, const BsdfFlags& /*flags*/, int /*bounces*/) { return true; }
    // The vertex drew the direction that continues the path: `sample` with |cos θ_i| = cos_i, the throughput
    // before it `beta` (after it: β f cos_i / pdf).
    virtual void sampled(const Color& /*beta*/, const BsdfSample& /*sample*/, Real /*cos_i*/) {}
};

}  // namespace rt
