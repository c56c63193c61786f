// Forward (light) tracing: paths start at the lights and bounce by the same BRDFs as chapter 06's paths
// (a BRDF is reciprocal, f(wo, wi) = f(wi, wo), so sampling wi from wo = the direction the light came from
// is the same sampler). With throughput β_k = β₀ Π f cos θ / pdf after k bounces, a path reaches the camera
// two ways:
//   aperture: the camera is a lens of radius R focused at infinity; a segment that happens to cross it adds
//             β We / A_lens to the pixel its direction maps to (We = pinhole_importance, A_lens = π R²).
//             Almost no path crosses a small lens: the fraction is measured.
//   connect:  at every non-specular vertex x (and at the light's own point), a visibility ray toward the
//             pinhole, and the splat  β f(wo, x→eye) G We,  G the geometry term (cos θ_c dω per dA(x)),
//             into the pixel x projects to. A mirror vertex cannot be connected (its f is a delta), so what a
//             mirror shows is lost to this camera.
// Glass (chapter 07's smooth dielectric): reflection with probability R, transmission with T; a light path
// carries power, which crosses an interface unscaled (T of it goes through), so its weight is 1 either way —
// not the 1 / η² of a radiance path. Inside absorbing glass β is multiplied by exp(−σ_a d) per segment.
// Rays: the ray leaving a light is counted as a shadow ray (it joins a light and a surface, as a shadow ray
// does, traced from the light's end); the connection rays as camera rays (they are the rays that reach the
// camera); bounces as indirect (Lambert) or reflection (mirror, glossy, retro-reflective), as in chapter 06.
#pragma once

#include "01_ray_generation/camera.hpp"
#include "02_intersection/hit.hpp"
#include "02_intersection/world.hpp"
#include "04_direct_lighting/bsdf.hpp"
#include "04_direct_lighting/light_set.hpp"
#include "04_direct_lighting/material_table.hpp"
#include "04_direct_lighting/trace_options.hpp"
#include "05_recursive_gi/termination.hpp"
#include "camera_importance.hpp"
#include "light_emission.hpp"
#include "rt/core/enum_names.hpp"
#include "rt/core/random.hpp"
#include "rt/core/ray_counts.hpp"
#include "splat_render.hpp"

namespace rt {

enum class CameraVariant { kConnect, kAperture };

constexpr auto names_of(CameraVariant) {
    return enum_names<CameraVariant>("--variant",
                                     {{CameraVariant::kConnect, "connect"}, {CameraVariant::kAperture, "aperture"}});
}

// Which light paths a tracer counts, by the vertices next to the camera (D a non-delta vertex, S a delta
// one):
//   all:      every path it finds;
//   caustics: light that reached the camera through at most K = caustic_bounces non-delta vertices after a
//             delta one, L…S D{1..K} E (K = 1: light that arrived at the connected vertex straight from a
//             mirror or glass). They are the paths chapter 06's loop leaves out with
//             CameraCausticCut(K) (camera_caustic_cut.hpp).
enum class LightPathSet { kAll, kCaustics };

// Effects read: "camera" (the emitters themselves, seen by the camera), "direct" (vertices after no diffuse
// or glossy bounce), "indirect" (bounces off diffuse and glossy surfaces). The material table — built for
// Transport::kImportance — holds what "glossy", "reflection" and "refraction" change.
struct LightTracerOptions : TraceOptions {
    CameraVariant variant = CameraVariant::kConnect;
    Real aperture_radius = 1;  // kAperture: the lens radius R, in scene units
    // Chapter 05's Russian roulette on the relative throughput Π f cos θ / pdf (β / β₀), under its cap.
    TerminationSettings termination{Termination::kRussianRoulette, kSafetyDepthCap};
    LightPathSet paths = LightPathSet::kAll;
    int caustic_bounces = 1;  // K, with LightPathSet::kCaustics
};

class LightTracer {
  public:
    // `materials` carries importance (Transport::kImportance); `world` and `materials` must outlive it.
    LightTracer(const World& world, const MaterialTable& materials, const LightSet& lights,
                const PinholeCamera& camera, LightTracerOptions options);

    // Traces one light path, adding its contributions to `film` (pixel sums). Returns whether it added any.
    bool trace(Pcg32& rng, Image& film, RayCounts& rays) const;

    const LightTracerOptions& options() const { return options_; }
    const EmitterSampler& emitters() const { return emitters_; }

    // The splat of a connection at surface vertex `hit` reached with throughput β from direction wo:
    // β f(wo, wc) cos θ_x cos θ_c We / r², wc the unit direction to the eye. Adds it to `film` when the eye
    // is visible (one camera ray) and returns whether it did.
    bool connect(const Hit& hit, const Vec3& wo, const Bsdf& bsdf, const Color& beta, Image& film,
                 RayCounts& rays) const;
    // The light's own point seen by the camera: Le cos θ_l cos θ_c We / (P pdf_A r²). A point light is not
    // seen (nothing, as in every chapter: no camera ray can hit a point; its pixel would read I We cos / r²).
    bool connect_light(const EmissionSample& emission, Image& film, RayCounts& rays) const;
    // The segment ray (0, t_hit) crossing the lens disc (centre eye, normal w, radius R) travelling toward
    // the film: adds β We / (π R²) to the pixel of direction −d.
    bool through_aperture(const Ray& ray, Real t_hit, const Color& beta, Image& film) const;

  private:
    const World& world_;
    const MaterialTable& materials_;
    PinholeCamera camera_;
    EmitterSampler emitters_;
    LightTracerOptions options_;
};

// Each light path traced by `tracer` (not copied: it must outlive the function).
LightPathFunction light_paths_of(const LightTracer& tracer);
// N light paths with `tracer` (deterministic for any thread count, see splat_render.hpp).
SplatResult render_light_tracing(const LightTracer& tracer, const RenderSettings& settings,
                                 std::uint64_t path_count);
// The light paths that match settings' camera samples one for one: spp × width × height.
std::uint64_t paths_per_image(const RenderSettings& settings);

}  // namespace rt
