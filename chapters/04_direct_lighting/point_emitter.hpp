// A point light as a Light: a delta (point_light_sampling.hpp), which emits Φ = 4π lum(I).
#pragma once

#include "light.hpp"
#include "point_light_sampling.hpp"

namespace rt {

class PointEmitter final : public Light {
  public:
    explicit PointEmitter(const PointLight& point) : point_(point) {}

    const PointLight& point() const { return point_; }

    std::optional<LightSample> sample(const Vec3& p, Vec2, QuadLightSampling) const override {
        return sample_point_light(point_, p);
    }
    Real pdf(const Vec3&, const Vec3&, const Hit&, const PickedLight&) const override { return 0; }
    Real power_weight() const override { return 4 * luminance(point_.intensity); }
    bool is_delta() const override { return true; }
    std::string_view kind() const override { return "point"; }

  private:
    PointLight point_;
};

}  // namespace rt
