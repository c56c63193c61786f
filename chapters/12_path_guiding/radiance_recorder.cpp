#include "radiance_recorder.hpp"

#include <algorithm>

namespace rt {

bool RadianceRecorder::reached(const Hit& hit, const BsdfFlags& flags, int /*bounces*/) {
    if (!vertices_.empty() && !vertices_.back().reached) {
        vertices_.back().arrived = path_.L;
        vertices_.back().reached = true;
    }
    point_ = hit.point;
    delta_ = flags.delta;
    return true;
}

void RadianceRecorder::sampled(const Color& beta, const BsdfSample& sample, Real cos_i) {
    if (delta_) return;
    vertices_.push_back({point_, sample.wi, sample.pdf, beta * sample.f * (cos_i / sample.pdf)});
}

void RadianceRecorder::record() const {
    // EXERCISE(ch12.incident_radiance) § 4. Learning from paths
    for (const Vertex& v : vertices_) {
        const Color after = v.reached ? glm::max(path_.L - v.arrived, Color(0)) : Color(0);
        Real sum = 0;
        int channels = 0;
        for (int c = 0; c < 3; ++c) {
            if (!(v.beta_after[c] > 0)) continue;
            sum += after[c] / v.beta_after[c];
            ++channels;
        }
        const Real incident = channels > 0 ? sum / Real(channels) : Real(0);
        field_.record(v.point, v.wi, incident / v.pdf);
    }
    // END EXERCISE
}

}  // namespace rt
