// An analysis of chapter 06's path loop, as the path's state (a PathState that files what L gains): the
// estimate L of one path split by the kind of path each term of it came from, so that a study can measure
// which kind of path carries a render's error. The loop is the same with it (the same random numbers, the
// same L); it files each term added:
//   seen:       light met by the camera ray, or by a chain of delta bounces from the camera (L-S*-E);
//   next event: light sampling at a non-delta vertex (chapter 04's estimate, MIS-weighted with BSDF hits);
//   BSDF hit:   light met by a ray a non-delta vertex drew from its BSDF, MIS-weighted against light
//               sampling (L-D-…);
//   caustic:    light met after a delta chain (glass, mirrors) that a non-delta vertex's BSDF sample
//               started (L-S+-D-…): light sampling cannot find these paths (its shadow rays stop at the
//               glass), so BSDF sampling alone carries them, at full weight;
// and files it again by the path's length, its non-delta bounces from the light to the camera: 0 (seen),
// 1 (direct light), 2, 3, and 4 or more.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>

#include "06_monte_carlo/path_tracer.hpp"
#include "rt/core/enum_names.hpp"
#include "rt/core/math.hpp"

namespace rt {

enum class PathPart : std::size_t { kSeen, kNextEvent, kBsdfHit, kCaustic };
inline constexpr std::size_t kPathPartCount = 4;
inline constexpr std::size_t kPathLengthCount = 5;  // 0, 1, 2, 3, and 4 or more bounces

constexpr auto names_of(PathPart) {
    return enum_names<PathPart>("path part", {{PathPart::kSeen, "seen"},
                                              {PathPart::kNextEvent, "next event"},
                                              {PathPart::kBsdfHit, "BSDF hit"},
                                              {PathPart::kCaustic, "caustic"}});
}

// PathTracer::radiance(ray, rng, rays, &parts) traces a path with it: a fresh one per path.
class PathParts final : public PathState {
  public:
    std::array<Color, kPathPartCount> parts{};      // their sum is the path's L
    std::array<Color, kPathLengthCount> lengths{};  // the same L by length: their sum is L too

    // Light met from the vertex `from`, after `bounces` non-delta bounces.
    void add_met(const Color& term) {
        L += term;
        file(!from.specular ? PathPart::kBsdfHit
             : bounces == 0 ? PathPart::kSeen
                            : PathPart::kCaustic,
             bounces, term);
    }
    // The light that a vertex reached after k bounces estimates has bounced once more, there.
    void add_estimate(const Color& term) {
        L += term;
        file(PathPart::kNextEvent, bounces + 1, term);
    }

  private:
    void file(PathPart part, int length, const Color& term) {
        parts[std::size_t(part)] += term;
        lengths[std::min(std::size_t(length), kPathLengthCount - 1)] += term;
    }
};

}  // namespace rt
