// Chapter 06's path loop, guided: an extension (path_tracer.hpp's extension point) that changes one member,
// the surface vertex, to a GuidedVertex that draws from the guiding field where it learned something; and a
// tracer render_paths can run, which, while the field trains, hands each path to a RadianceRecorder.
#pragma once

#include "06_monte_carlo/path_tracer.hpp"
#include "guided_vertex.hpp"
#include "guiding_field.hpp"

namespace rt {

class GuidedPaths : public SurfacePaths {
  public:
    GuidedPaths(const PathTracer& tracer, const GuidingField& field) : SurfacePaths(tracer), field_(field) {}

    // Chapter 06's vertex, guided by the field's guide at the hit unless the BSDF is a delta.
    GuidedVertex vertex(const Hit& hit, const Vec3& wo, const Bsdf& bsdf) const {
        const BsdfFlags& flags = bsdf.flags();
        const DirectionalQuadtree* guide = flags.delta ? nullptr : field_.guide_at(hit.point);
        return {SurfacePaths::vertex(hit, wo, bsdf), flags.transmission, guide,
                field_.settings().guided_fraction};
    }

  private:
    const GuidingField& field_;
};

class GuidedTracer {
  public:
    // Paths of `tracer` guided by `field`; with `training`, each path is also recorded into it. Both must
    // outlive it.
    GuidedTracer(const PathTracer& tracer, GuidingField& field, bool training)
        : tracer_(tracer), field_(field), training_(training) {}

    // One path's estimate of the radiance along the camera ray `ray`.
    Color radiance(const Ray& ray, SampleStream rng, RayCounts& rays) const;
    const PathOptions& options() const { return tracer_.options(); }

  private:
    const PathTracer& tracer_;
    GuidingField& field_;
    bool training_;
};

}  // namespace rt
