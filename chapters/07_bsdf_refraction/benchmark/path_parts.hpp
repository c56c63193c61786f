// An analysis of chapter 06's path loop, as a PathObserver: the estimate L of one path split by the kind of
// path each term of it came from, so that a study can measure which kind of path carries a render's error.
// The loop is the same with or without it (the same random numbers, the same L); it files each term added:
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

#include "06_monte_carlo/path_observer.hpp"
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

class PathParts final : public PathObserver {
  public:
    std::array<Color, kPathPartCount> parts{};      // their sum is the path's L
    std::array<Color, kPathLengthCount> lengths{};  // the same L by length: their sum is L too

    bool reached(const Hit& /*hit*/, const BsdfFlags& /*flags*/, int bounces) override {
        vertex_bounces_ = bounces;
        return true;
    }
    void light_met(const Color& L, bool specular, int bounces) override {
        file(!specular      ? PathPart::kBsdfHit
             : bounces == 0 ? PathPart::kSeen
                            : PathPart::kCaustic,
             bounces, L);
    }
    // The light a vertex reached after k bounces estimates has bounced once more, there.
    void light_estimated(const Color& L) override { file(PathPart::kNextEvent, vertex_bounces_ + 1, L); }

  private:
    // Files what L gained since the last call as `part`, of `bounces` bounces.
    void file(PathPart part, int bounces, const Color& L) {
        parts[std::size_t(part)] += L - filed_;
        lengths[std::min(std::size_t(bounces), kPathLengthCount - 1)] += L - filed_;
        filed_ = L;
    }

    Color filed_{0};          // the part of L filed so far
    int vertex_bounces_ = 0;  // the bounces before the vertex the path is at
};

}  // namespace rt
