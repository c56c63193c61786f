#include "guided_tracer.hpp"

#include "radiance_recorder.hpp"

namespace rt {

Color GuidedTracer::radiance(const Ray& ray, SampleStream rng, RayCounts& rays) const {
    PathState path;
    const GuidedPaths paths(tracer_, field_);
    if (!training_) {
        tracer_.trace(ray, path, rng, rays, nullptr, paths);
        return path.L;
    }
    RadianceRecorder recorder(field_, path);
    tracer_.trace(ray, path, rng, rays, &recorder, paths);
    recorder.record();
    return path.L;
}

}  // namespace rt
