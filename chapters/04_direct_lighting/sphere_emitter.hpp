// A sphere light (an emissive sphere) as a Light: sampled by solid angle, uniformly in the cone it fills
// (sphere_light_sampling.hpp).
#pragma once

#include "light.hpp"
#include "sphere_light_sampling.hpp"

namespace rt {

class SphereEmitter final : public Light {
  public:
    explicit SphereEmitter(const SphereLight& sphere) : sphere_(sphere) {}

    const SphereLight& sphere() const { return sphere_; }

    std::optional<LightSample> sample(const Vec3& p, Vec2 u, QuadLightSampling) const override {
        return sample_sphere_light(sphere_, p, u);
    }
    Real pdf(const Vec3& p, const Vec3&, const Hit&, const PickedLight& picked) const override {
        return picked.probability * sphere_light_pdf(sphere_, p);
    }
    Real power_weight() const override { return luminance(sphere_.radiance) * area_of(sphere_); }
    bool is_delta() const override { return false; }
    std::string_view kind() const override { return "sphere"; }

  private:
    SphereLight sphere_;
};

}  // namespace rt
