// A spot light (pbrt-v4's): a point light whose intensity I is sent into a cone about its axis, from
// `position` toward `at`. Along a direction at angle θ from the axis it sends I × falloff(cos θ): 1 within
// cone_angle − cone_delta, 0 beyond cone_angle, and between them smoothstep in cos θ, so the edge is soft.
// Seen from p it is a point light (point_light_sampling.hpp) dimmed by its falloff toward p. It emits
// Φ = 2π I (1 − (cos θ_start + cos θ_end) / 2): the full cone to the falloff's start, half the band.
#pragma once

#include <algorithm>
#include <cmath>

#include "light.hpp"
#include "point_light_sampling.hpp"
#include "rt/core/scene.hpp"

namespace rt {

class SpotEmitter final : public Light {
  public:
    explicit SpotEmitter(const SpotLight& spot)
        : spot_(spot),
          axis_(glm::normalize(spot.at - spot.position)),
          cos_end_(std::cos(radians(spot.cone_angle))),
          cos_start_(std::cos(radians(spot.cone_angle - spot.cone_delta))) {}

    const SpotLight& spot() const { return spot_; }
    const Vec3& axis() const { return axis_; }
    Real cos_end() const { return cos_end_; }
    Real cos_start() const { return cos_start_; }

    // The fraction of I sent along the unit direction w: smoothstep from cos θ_end (0) to cos θ_start (1);
    // a step at the cone's edge when they are equal (cone_delta = 0).
    Real falloff(const Vec3& w) const {
        const Real c = glm::dot(axis_, w);
        if (!(cos_start_ > cos_end_)) return c < cos_end_ ? Real(0) : Real(1);
        const Real t = std::clamp((c - cos_end_) / (cos_start_ - cos_end_), Real(0), Real(1));
        return t * t * (3 - 2 * t);
    }

    // Nothing outside the cone: no shadow ray for a point it does not light.
    std::optional<LightSample> sample(const Vec3& p, Vec2, QuadLightSampling) const override {
        auto s = sample_point_light(PointLight{spot_.position, spot_.intensity}, p);
        if (!s) return std::nullopt;
        const Real f = falloff(-s->wi);
        if (!(f > 0)) return std::nullopt;
        s->radiance *= f;
        return s;
    }
    Real pdf(const Vec3&, const Vec3&, const Hit&, const PickedLight&) const override { return 0; }
    // Φ / π = 2 lum(I) (1 − (cos θ_start + cos θ_end) / 2).
    Real power_weight() const override {
        return 2 * luminance(spot_.intensity) * (1 - (cos_start_ + cos_end_) / 2);
    }
    bool is_delta() const override { return true; }
    std::string_view kind() const override { return "spot"; }

  private:
    SpotLight spot_;
    Vec3 axis_;
    Real cos_end_;    // cos(cone_angle)
    Real cos_start_;  // cos(cone_angle − cone_delta)
};

}  // namespace rt
