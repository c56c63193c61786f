// What a training path teaches the guiding field. It watches the path (a PathObserver of chapter 06: the
// loop is not copied) and notes, at each vertex k that drew its continuation wi with density p, the
// throughput β_{k+1} = β_k f |cos θ_i| / p after it, and the radiance L_{k+1} the path had gathered when it
// reached its next vertex (the light met there included). When the path ends with L, what it gathered after
// that arrived at x_k along wi by scattering at the next vertex, so
//   L_i(x_k, wi) ≈ (L − L_{k+1}) / β_{k+1}   (per colour channel; their mean)
// estimates the indirect radiance incident at x_k from wi: the light that next-event estimation cannot
// find. (An emitter seen straight along wi is next-event estimation's, and a guide that learned it would
// spend its samples where light sampling already does well.) The field records it with weight L_i / p:
// summed over a pass, each quadrant's weights estimate ∫ L_i dω over its solid angle. Delta vertices are
// not recorded (they are never guided), but reaching one is reaching the next vertex.
#pragma once

#include <vector>

#include "06_monte_carlo/path_observer.hpp"
#include "06_monte_carlo/path_tracer.hpp"
#include "guiding_field.hpp"

namespace rt {

class RadianceRecorder : public PathObserver {
  public:
    // Watches `path` (its L) for `field`; both must outlive it.
    RadianceRecorder(GuidingField& field, const PathState& path) : field_(field), path_(path) {}

    bool reached(const Hit& hit, const BsdfFlags& flags, int bounces) override;
    void sampled(const Color& beta, const BsdfSample& sample, Real cos_i) override;
    // The path has ended: records each noted vertex into the field.
    void record() const;

  private:
    struct Vertex {
        Vec3 point, wi;
        Real pdf;
        Color beta_after;      // β_{k+1}
        Color arrived{0};      // L_{k+1}
        bool reached = false;  // whether the path reached a next vertex (else nothing arrived by scattering)
    };
    GuidingField& field_;
    const PathState& path_;
    Vec3 point_{0};
    bool delta_ = false;
    std::vector<Vertex> vertices_;
};

}  // namespace rt
