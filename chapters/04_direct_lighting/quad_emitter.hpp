// A quad light (an emissive quad, or a face of an emissive box) as a Light: sampled by area or by solid
// angle (quad_light_strategy.hpp). A direction that met it was drawn with P / Ω where the spherical
// rectangle serves, with the planar density elsewhere.
#pragma once

#include "area_light_sampling.hpp"
#include "light.hpp"
#include "quad_light_strategy.hpp"

namespace rt {

class QuadEmitter final : public Light {
  public:
    explicit QuadEmitter(const QuadLight& quad) : quad_(quad) {}

    const QuadLight& quad() const { return quad_; }

    std::optional<LightSample> sample(const Vec3& p, Vec2 u, QuadLightSampling quads) const override {
        if (quad_.two_sided) return sample_quad_light(facing(quad_, p), p, u, quads);
        return sample_quad_light(quad_, p, u, quads);  // one-sided: no copy on the hot path
    }
    Real pdf(const Vec3& p, const Vec3& wi, const Hit& hit, const PickedLight& picked) const override {
        if (quad_.two_sided) {
            const QuadLight quad = facing(quad_, p);
            return pdf_of(quad, quad.normal, p, wi, hit.t, picked);
        }
        return pdf_of(quad_, hit.normal, p, wi, hit.t, picked);
    }
    Real power_weight() const override { return luminance(quad_.radiance) * area_of(quad_) * sides(quad_); }
    bool is_delta() const override { return false; }
    std::string_view kind() const override { return "quad"; }

  private:
    // The density of wi toward `quad`, the one-sided light p sees, hit at distance t where its normal is n.
    static Real pdf_of(const QuadLight& quad, const Vec3& n, const Vec3& p, const Vec3& wi, Real t,
                       const PickedLight& picked) {
        const Real cos_light = -glm::dot(n, wi);
        if (!(cos_light > 0)) return 0;
        if (picked.quads == QuadLightSampling::kSolidAngle) {
            if (const auto view = solid_angle_view(quad, p))
                return picked.probability * Real(1 / view->solid_angle());
        }
        return picked_planar_pdf(quad.radiance, t, cos_light, picked.total_weight) * sides(quad);
    }

    QuadLight quad_;
};

}  // namespace rt
