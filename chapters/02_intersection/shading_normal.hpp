// The shading normal of a smooth mesh: its vertex normals n0, n1, n2 interpolated with the hit's
// barycentrics, ns = normalize(b0 n0 + b1 n1 + b2 n2). It only approximates a curved surface the triangles
// stand in for, so it disagrees with the geometric normal ng, and two cases go wrong if nothing is done:
//  - ns facing away from the viewer (dot(wo, ns) <= 0, near a silhouette): every BRDF sees wo below its
//    surface and returns 0, a black fringe;
//  - ns on the other side of the surface than ng (vertex normals that disagree with the winding): the BSDF
//    reflects light as if it came through the surface, a leak.
// The course's one fix, made here and nowhere else: flip ns into ng's hemisphere (as pbrt-v4 does), then bend
// it, in the plane of wo and ns, just far enough that wo is kShadingHorizon above its horizon.
#pragma once

#include "rt/core/enum_names.hpp"
#include "rt/core/math.hpp"

namespace rt {

// kBend: the fix above; kNone: the interpolated normal, only turned to the viewer's side with the geometric
// one (to measure what the fix buys); kFlat: the geometric normal (the mesh faceted).
enum class ShadingNormalFix { kBend, kNone, kFlat };

constexpr auto names_of(ShadingNormalFix) {
    return enum_names<ShadingNormalFix>("--shading-normals", {{ShadingNormalFix::kBend, "bend"},
                                                              {ShadingNormalFix::kNone, "raw"},
                                                              {ShadingNormalFix::kFlat, "flat"}});
}

// cos of the smallest angle the fix leaves between wo and the shading horizon: wo · ns >= kShadingHorizon.
inline constexpr Real kShadingHorizon = Real(0.01);

// The shading normal for the interpolated (unit) normal `interpolated`, the unit geometric normal `geometric`
// facing the viewer (Hit::normal) and the unit direction `wo` toward the viewer.
Vec3 shading_normal(const Vec3& interpolated, const Vec3& geometric, const Vec3& wo, ShadingNormalFix fix);

}  // namespace rt
