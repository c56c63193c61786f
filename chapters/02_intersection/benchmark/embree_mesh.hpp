// Embree 3 (Intel's ray tracing kernels, Debian's libembree-dev), for ch02_benchmark --embree only: one mesh
// in an Embree scene, traced one ray at a time (rtcIntersect1, rtcOccluded1), so the course's BVH can be
// measured against it on the same rays. Built only when CMake finds Embree; nothing else uses it.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>

#include "hit.hpp"
#include "rt/core/ray.hpp"
#include "rt/core/scene.hpp"

namespace rt {

// The version of the Embree headers built against, as "3.13.5".
const char* embree_version();

class EmbreeMesh {
  public:
    // Builds Embree's BVH over the mesh with its default settings, or with RTC_SCENE_FLAG_ROBUST (which
    // "avoids optimizations that reduce arithmetic accuracy").
    EmbreeMesh(const MeshShape& mesh, bool robust);
    ~EmbreeMesh();
    EmbreeMesh(const EmbreeMesh&) = delete;
    EmbreeMesh& operator=(const EmbreeMesh&) = delete;

    // The nearest hit with t in [0, t_max], as Embree's nearest-hit query (rtcIntersect1) reports it: its
    // distance, the triangle's number in the mesh and the barycentrics (u, v) of its second and third
    // corners. What World::nearest reports, in the same form.
    std::optional<NearestHit> intersect(const Ray& ray, Real t_max) const;
    // The same, answered by Embree's any-hit query.
    bool occluded(const Ray& ray, Real t_max) const;
    // The bytes Embree allocated for the scene (its BVH and its triangle copies), as its memory monitor
    // reports them.
    std::size_t bytes() const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace rt
