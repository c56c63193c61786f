// Two ways to sample a quad light from p (`--quad-lights`): by area (a uniform point on it, pdf_ω =
// d² / (cos θ_l A), area_light_sampling.hpp), or by solid angle (a uniform direction in the spherical
// rectangle it subtends, pdf_ω = 1 / Ω, spherical_rectangle.hpp), which has no 1 / cos θ_l d² to blow up
// near a large, close lamp. Solid angle serves only where its maths holds, area sampling everywhere else:
//   - a parallelogram (U not perpendicular to V) has no spherical rectangle;
//   - below Ω = 1e-4 sr (small or far) Ω is a difference of angles near 2π that loses its digits, and area
//     sampling is already nearly uniform in solid angle there;
//   - above Ω = 6.2 sr (p almost on the lamp) the corners' normals are nearly parallel to the plane.
// (pbrt-v4 keeps such bounds on its spherical triangle and rectangle sampling too.) Both the sample and the
// pdf ask solid_angle_view, so MIS weighs each direction with the density that drew it.
#pragma once

#include <optional>

#include "area_light_sampling.hpp"
#include "area_lights.hpp"
#include "light_sample.hpp"
#include "rt/core/enum_names.hpp"
#include "spherical_rectangle.hpp"

namespace rt {

enum class QuadLightSampling { kArea, kSolidAngle };

constexpr auto names_of(QuadLightSampling) {
    return enum_names<QuadLightSampling>("--quad-lights", {{QuadLightSampling::kArea, "area"},
                                                           {QuadLightSampling::kSolidAngle, "solid-angle"}});
}

inline constexpr double kMinSphericalSolidAngle = 1e-4;  // sr
inline constexpr double kMaxSphericalSolidAngle = 6.2;   // sr (2π = 6.283)
// |cos| of the angle between U and V up to which a quad counts as a rectangle.
inline constexpr Real kRectangleCosine = Real(1e-5);

// The spherical rectangle that solid-angle sampling uses for `light` from p; nothing where area sampling
// serves instead (a parallelogram, p behind the lamp or in its plane, Ω outside the bounds above).
std::optional<SphericalRectangle> solid_angle_view(const QuadLight& light, const Vec3& p);

// A sample of `light` from p by solid angle (area sampling wherever solid_angle_view gives nothing).
std::optional<LightSample> sample_quad_light_by_solid_angle(const QuadLight& light, const Vec3& p, Vec2 u);
// A sample of `light` from p by `strategy`. Inline, so that the default, area sampling, costs one comparison
// more than calling the area sampler itself.
inline std::optional<LightSample> sample_quad_light(const QuadLight& light, const Vec3& p, Vec2 u,
                                                    QuadLightSampling strategy) {
    if (strategy == QuadLightSampling::kArea) return sample_quad_light(light, p, u);
    return sample_quad_light_by_solid_angle(light, p, u);
}
// The solid-angle density with which that sampler draws wi from p (0 if wi misses the light).
Real quad_light_pdf(const QuadLight& light, const Vec3& p, const Vec3& wi, QuadLightSampling strategy);

}  // namespace rt
