// A distant light (the sun): parallel light travelling along one direction, so every point p receives it
// from wi = −direction, unshadowed, with irradiance E on a surface facing it: a delta, whose one direction
// carries L_e / pdf = E (pdf 1), and a diffuse surface of albedo a tilted by θ reads a E cos θ / π.
// It lights the whole scene, so its power is E times the area the scene shows it: pbrt's Φ = π r² E, r the
// radius of the sphere around every shape.
#pragma once

#include <algorithm>

#include "light.hpp"
#include "rt/core/scene.hpp"

namespace rt {

// The sphere around every shape of a scene (an emissive plane's point included: planes have no bound).
struct BoundingSphere {
    Vec3 center{0};
    Real radius = 0;
};

class DistantEmitter final : public Light {
  public:
    DistantEmitter(const DistantLight& light, const BoundingSphere& scene) : light_(light), scene_(scene) {}

    const DistantLight& light() const { return light_; }
    const BoundingSphere& scene() const { return scene_; }

    // The shadow ray runs from p to a point past every shape: |p − c| + 2r away (at least 1: a scene of
    // planes alone has r = 0).
    std::optional<LightSample> sample(const Vec3& p, Vec2, QuadLightSampling) const override {
        const Vec3 wi = -light_.direction;
        const Real reach = std::max(Real(1), glm::length(p - scene_.center) + 2 * scene_.radius);
        return LightSample{p + reach * wi, wi, reach, light_.irradiance, 1};
    }
    Real pdf(const Vec3&, const Vec3&, const Hit&, const PickedLight&) const override { return 0; }
    // Φ / π = r² lum(E).
    Real power_weight() const override {
        return scene_.radius * scene_.radius * luminance(light_.irradiance);
    }
    bool is_delta() const override { return true; }
    std::string_view kind() const override { return "distant"; }

  private:
    DistantLight light_;
    BoundingSphere scene_;
};

}  // namespace rt
