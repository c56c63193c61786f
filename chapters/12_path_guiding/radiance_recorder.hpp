// What a training path teaches the guiding field. It watches the path (a PathObserver of chapter 06: the
// loop is not copied) and notes, at each vertex that drew its continuation wi with density p, the throughput
// β_{k+1} = β_k f |cos θ_i| / p after it and the radiance L_k the path had gathered so far. When the path
// ends with L, everything gathered after vertex k arrived there along wi, so
//   L_i(x_k, wi) ≈ (L − L_k) / β_{k+1}   (per colour channel; their mean),
// an estimate of the incident radiance, which the field records with weight L_i / p: summed over a pass,
// each quadrant's weights estimate ∫ L_i dω over its solid angle. Delta vertices are not recorded (they
// are never guided).
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
        Color beta_after, gathered;  // β_{k+1}, L_k
    };
    GuidingField& field_;
    const PathState& path_;
    Vec3 point_{0};
    bool delta_ = false;
    std::vector<Vertex> vertices_;
};

}  // namespace rt
