#include "light_tracer.hpp"

#include <cmath>
#include <string>

#include "03_shadow_rays/shadow_ray.hpp"
#include "rt/core/errors.hpp"

namespace rt {
namespace {

// Adds c to pixel (x, y) unless it is zero or not finite; returns whether it did.
bool splat(Image& film, const FilmPoint& p, const Color& c) {
    if (is_black(c) || !is_finite(c)) return false;
    film.at(p.x, p.y) += c;
    return true;
}

}  // namespace

LightTracer::LightTracer(const World& world, const MaterialTable& materials, const LightSet& lights,
                         const PinholeCamera& camera, LightTracerOptions options)
    : world_(world), materials_(materials), camera_(camera), emitters_(lights), options_(options) {
    if (options_.variant == CameraVariant::kAperture && !(options_.aperture_radius > 0)) {
        throw InputError("--aperture: the lens radius must be > 0, got " +
                         std::to_string(options_.aperture_radius));
    }
    if (options_.variant == CameraVariant::kAperture && options_.paths != LightPathSet::kAll)
        throw InputError("caustics alone are traced with --variant connect (a lens sees every path)");
}

bool LightTracer::connect(const Hit& hit, const Vec3& wo, const Bsdf& bsdf, const Color& beta, Image& film,
                          RayCounts& rays) const {
    // EXERCISE(ch08.connect) § Reaching the camera
    const Vec3 to_eye = camera_.eye - hit.point;
    const Real r2 = glm::dot(to_eye, to_eye);
    if (!(r2 > 0)) return false;
    const Vec3 wc = to_eye / std::sqrt(r2);
    // |cos θ_x| on the eye's side; a BSDF that transmits also reaches an eye behind the surface.
    const Real dot_x = glm::dot(wc, hit.normal);
    const Real cos_x = bsdf.flags().transmission ? std::abs(dot_x) : dot_x;
    if (!(cos_x > 0)) return false;
    const auto p = project_direction(camera_, -to_eye);
    if (!p) return false;
    const Color f = bsdf.eval(wo, wc, hit.normal);
    if (is_black(f)) return false;
    const ShadowRay s = spawn_shadow_ray(hit, camera_.eye, options_.offset);
    rays.add(RayKind::kCamera);
    if (world_.occluded(s.ray, s.t_max)) return false;
    const Real G = cos_x * p->cos_theta / r2;
    return splat(film, *p, beta * f * (G * pinhole_importance(camera_, p->cos_theta)));
    // END EXERCISE
}

bool LightTracer::connect_light(const EmissionSample& e, Image& film, RayCounts& rays) const {
    if (e.delta_light) return false;
    const Vec3 to_eye = camera_.eye - e.origin.point;
    const Real r2 = glm::dot(to_eye, to_eye);
    if (!(r2 > 0)) return false;
    const Vec3 wc = to_eye / std::sqrt(r2);
    // One-sided: an area light emits on its normal's side only.
    const Real cos_l = glm::dot(wc, e.origin.normal);
    if (!(cos_l > 0)) return false;
    const auto p = project_direction(camera_, -to_eye);
    if (!p) return false;
    rays.add(RayKind::kCamera);
    const ShadowRay s = spawn_shadow_ray(e.origin, camera_.eye, options_.offset);
    if (world_.occluded(s.ray, s.t_max)) return false;
    const Real G = cos_l * p->cos_theta / r2;
    return splat(film, *p, e.position_weight * (G * pinhole_importance(camera_, p->cos_theta)));
}

bool LightTracer::through_aperture(const Ray& ray, Real t_hit, const Color& beta, Image& film) const {
    const Real facing = glm::dot(ray.direction, camera_.forward);
    if (!(facing < 0)) return false;  // only light travelling toward the film enters the lens
    const Real t = glm::dot(camera_.eye - ray.origin, camera_.forward) / facing;
    if (!(t > 0 && t < t_hit)) return false;
    const Vec3 offset = ray.at(t) - camera_.eye;
    const Real R = options_.aperture_radius;
    if (glm::dot(offset, offset) > R * R) return false;
    const auto p = project_direction(camera_, -ray.direction);
    if (!p) return false;
    const Real lens_area = kPi * R * R;
    return splat(film, *p, beta * (pinhole_importance(camera_, p->cos_theta) / lens_area));
}

bool LightTracer::trace(Pcg32& rng, Image& film, RayCounts& rays) const {
    const Real u_pick = rng.next_real();
    const Vec2 u_point = rng.next_vec2();
    const Vec2 u_direction = rng.next_vec2();
    const auto e = emitters_.sample(u_pick, u_point, u_direction);
    if (!e) return false;
    const bool connecting = options_.variant == CameraVariant::kConnect;
    bool added = false;
    const LightPathSet wanted_paths = options_.paths;
    if (connecting && options_.simulates(Effect::kCameraRays) && wanted_paths == LightPathSet::kAll)
        added |= connect_light(*e, film, rays);
    Ray ray = e->delta_light ? Ray{e->origin.point, e->direction}
                             : spawn_ray(e->origin, e->direction, options_.offset);
    rays.add(RayKind::kShadow);
    Color relative(1);         // Π f cos θ / pdf: β = β₀ relative
    int diffuse_bounces = 0;   // non-specular bounces so far
    int since_mirror = -1;     // non-specular vertices since the last specular one (−1: none yet)
    for (int depth = 0;; ++depth) {
        const Color beta = e->beta * relative;
        const auto hit = world_.intersect(ray);
        if (!connecting) added |= through_aperture(ray, hit ? hit->t : kInfinity, beta, film);
        if (!hit) break;
        // A segment that ends on the inside of a shape ran through what fills it (Beer–Lambert in glass).
        if (!hit->front_face) {
            if (const Medium* medium = materials_.interior(hit->material))
                relative *= medium->transmittance(hit->t);
        }
        BsdfAtHit at;
        const Bsdf& bsdf = materials_.bsdf(*hit, at);
        const BsdfFlags& flags = bsdf.flags();
        if (flags.black) break;
        const Vec3 wo = -ray.direction;
        since_mirror = flags.delta ? 0 : since_mirror < 0 ? -1 : since_mirror + 1;
        // A delta vertex (mirror, smooth glass) cannot be connected: its f is 0 toward the pinhole.
        if (connecting && !flags.delta) {
            const bool wanted = diffuse_bounces == 0 ? options_.simulates(Effect::kDirect)
                                                     : options_.simulates(Effect::kIndirect);
            // Caustics: this vertex is one of the first K non-delta ones after a delta one, L…S D{1..K} E.
            const bool caustic = since_mirror >= 1 && since_mirror <= options_.caustic_bounces;
            if (wanted && (wanted_paths == LightPathSet::kAll || caustic))
                added |= connect(*hit, wo, bsdf, beta, film, rays);
        }
        // Without the indirect effect a path ends at its first diffuse vertex: maximum depth 1.
        if (!flags.delta && !options_.simulates(Effect::kIndirect)) break;
        const Vec2 u = rng.next_vec2();
        const BsdfSample s = bsdf.sample(wo, hit->normal, u, flags.transmission ? rng.next_real() : Real(0));
        const Real cos_i = scattering_cosine(s.wi, hit->normal, s.transmitted);
        if (!(cos_i > 0) || !(s.pdf > 0) || is_black(s.f)) break;
        relative *= s.f * (cos_i / s.pdf);
        if (!s.delta) ++diffuse_bounces;
        if (!continue_path(options_.termination, depth + 1, relative, rng.next_real())) break;
        ray = spawn_ray(*hit, s.wi, options_.offset);
        rays.add(ray_kind(flags, s.transmitted));
    }
    return added;
}

LightPathFunction light_paths_of(const LightTracer& tracer) {
    return [&tracer](std::uint64_t, Pcg32& rng, Image& film, RayCounts& rays) {
        return tracer.trace(rng, film, rays);
    };
}

SplatResult render_light_tracing(const LightTracer& tracer, const RenderSettings& settings,
                                 std::uint64_t path_count) {
    return render_light_paths(settings, path_count, light_paths_of(tracer));
}

std::uint64_t paths_per_image(const RenderSettings& settings) {
    return std::uint64_t(settings.samples_per_pixel) * std::uint64_t(settings.width) *
           std::uint64_t(settings.height);
}

}  // namespace rt
