// A triangle light (an emissive triangle, or a triangle of an emissive mesh) as a Light: sampled by area
// (area_light_sampling.hpp).
#pragma once

#include "area_light_sampling.hpp"
#include "light.hpp"

namespace rt {

class TriangleEmitter final : public Light {
  public:
    explicit TriangleEmitter(const TriangleLight& triangle) : triangle_(triangle) {}

    const TriangleLight& triangle() const { return triangle_; }

    std::optional<LightSample> sample(const Vec3& p, Vec2 u, QuadLightSampling) const override {
        if (triangle_.two_sided) return sample_triangle_light(facing(triangle_, p), p, u);
        return sample_triangle_light(triangle_, p, u);  // one-sided: no copy on the hot path
    }
    Real pdf(const Vec3& p, const Vec3& wi, const Hit& hit, const PickedLight& picked) const override {
        const Real cos_light = -glm::dot(triangle_.two_sided ? facing(triangle_, p).normal : hit.normal, wi);
        if (!(cos_light > 0)) return 0;
        return picked_planar_pdf(triangle_.radiance, hit.t, cos_light, picked.total_weight) *
               sides(triangle_);
    }
    Real power_weight() const override {
        return luminance(triangle_.radiance) * area_of(triangle_) * sides(triangle_);
    }
    bool is_delta() const override { return false; }
    std::string_view kind() const override { return "triangle"; }

  private:
    TriangleLight triangle_;
};

}  // namespace rt
