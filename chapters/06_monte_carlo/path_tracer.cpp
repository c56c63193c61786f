#include "path_tracer.hpp"

#include <algorithm>
#include <cmath>

#include "01_ray_generation/camera_render.hpp"
#include "03_shadow_rays/shadow_ray.hpp"
#include "04_direct_lighting/frame.hpp"
#include "04_direct_lighting/sampling.hpp"
#include "mis.hpp"
#include "warp_pdfs.hpp"

namespace rt {
PathTracer::PathTracer(const World& world, const MaterialTable& materials, const LightSet& lights,
                       PathOptions options)
    : world_(world),
      materials_(materials),
      picker_(lights),
      environment_(lights.environment),
      has_unsampled_emitters_(!lights.unsampled.empty()),
      exterior_(materials.exterior()),
      media_(exterior_ != nullptr),
      options_(options) {
    if (environment_ && is_black(environment_->radiance)) environment_.reset();
    for (std::size_t m = 0; m < materials.size(); ++m) {
        const Medium* inside = materials.interior(int(m));
        media_ = media_ || (inside && inside->phase());
    }
}

const Medium* PathTracer::medium_along(const std::optional<Hit>& end) const {
    if (end && !end->front_face && materials_.bsdf(end->material, false).flags().transmission)
        return materials_.interior(end->material);
    return exterior_;
}

Color PathTracer::transmittance(Ray ray, Real t_max, RayCounts& rays) const {
    // T = Π over the segments of exp(−σ_t d): each segment through the medium its end says, to the next
    // surface before t_max, which the ray crosses only if it is an index-matched boundary.
    Color T(1);
    for (;;) {
        rays.add(RayKind::kShadow);
        const auto hit = world_.intersect(ray, t_max);
        if (const Medium* medium = medium_along(hit)) T *= medium->transmittance(hit ? hit->t : t_max);
        if (!hit) return T;
        if (!materials_.bsdf(hit->material, hit->front_face).flags().index_matched || is_black(T))
            return Color(0);
        t_max -= hit->t;
        ray = spawn_ray(*hit, ray.direction, options_.offset);
    }
}

Color PathTracer::seen(const Hit& hit, const Vec3& target, RayCounts& rays) const {
    if (!media_) return Color(visible(world_, hit, target, options_.offset, rays) ? 1 : 0);
    const ShadowRay shadow = spawn_shadow_ray(hit, target, options_.offset);
    return transmittance(shadow.ray, shadow.t_max, rays);
}

Color PathTracer::next_event_in_medium(const Vec3& p, const Vec3& wo, const PhaseFunction& phase,
                                       SampleStream rng, RayCounts& rays) const {
    const bool mis = options_.strategy == SamplingStrategy::kMis;
    const bool shadows = options_.simulates(Effect::kShadows);
    Color sum(0);
    if (!picker_.empty()) {
        const Real u_pick = rng.next_real();
        const Vec2 u = rng.next_vec2();
        if (const auto s = picker_.sample(p, u_pick, u); s && s->pdf > 0) {
            const Real f = phase.eval(wo, s->wi);
            const Color T = f > 0 && shadows
                                ? transmittance({p, s->wi}, (1 - kShadowEpsilon) * s->distance, rays)
                                : Color(1);
            if (f > 0 && !is_black(T)) {
                const Real w =
                    mis && s->on_surface() ? power_heuristic(s->pdf, phase.pdf(wo, s->wi)) : Real(1);
                sum += T * s->radiance * (f * w / s->pdf);
            }
        }
    }
    if (environment_) {
        const Vec3 wi = sample_uniform_sphere(rng.next_vec2());
        const Real f = phase.eval(wo, wi);
        const Color T = f > 0 && shadows ? transmittance({p, wi}, kInfinity, rays) : Color(1);
        if (f > 0 && !is_black(T)) {
            const Real w = mis ? power_heuristic(kUniformSpherePdf, phase.pdf(wo, wi)) : Real(1);
            sum += T * environment_->radiance * (f * w / kUniformSpherePdf);
        }
    }
    return sum;
}

Color PathTracer::next_event(const Hit& hit, const Vec3& wo, const Bsdf& bsdf, SampleStream rng,
                             RayCounts& rays) const {
    const bool mis = options_.strategy == SamplingStrategy::kMis;
    const bool shadows = options_.simulates(Effect::kShadows);
    // A BSDF that transmits is lit from both sides; |cos θ_i| then weighs light from behind the surface.
    const bool both_sides = bsdf.flags().transmission;
    const Vec3& n = hit.normal;
    Color sum(0);
    if (!picker_.empty()) {
        const Real u_pick = rng.next_real();
        const Vec2 u = rng.next_vec2();
        if (const auto s = picker_.sample(hit.point, u_pick, u)) {
            const Real dot_i = glm::dot(s->wi, n);
            const Real cos_i = both_sides ? std::abs(dot_i) : dot_i;
            if (cos_i > 0 && s->pdf > 0) {
                const Color f = bsdf.eval(wo, s->wi, n);
                const Color T = !is_black(f) && shadows ? seen(hit, s->point, rays) : Color(1);
                if (!is_black(f) && !is_black(T)) {
                    // A point light is a delta: no BSDF sample can hit it, so its light sample has weight 1.
                    const Real w =
                        mis && s->on_surface() ? power_heuristic(s->pdf, bsdf.pdf(wo, s->wi, n)) : Real(1);
                    sum += f * T * s->radiance * (cos_i * w / s->pdf);
                }
            }
        }
    }
    if (environment_) {
        // The uniform environment is sampled like chapter 04's: cosine-weighted, pdf = cos θ / π.
        const Vec3 wi = glm::normalize(make_frame(n).to_world(sample_cosine_hemisphere(rng.next_vec2())));
        const Real cos_i = glm::dot(wi, n);
        const Color f = cos_i > 0 ? bsdf.eval(wo, wi, n) : Color(0);
        if (!is_black(f)) {
            Color T(1);
            if (shadows && media_) {
                T = transmittance(spawn_ray(hit, wi, options_.offset), kInfinity, rays);
            } else if (shadows) {
                rays.add(RayKind::kShadow);
                T = Color(world_.occluded(spawn_ray(hit, wi, options_.offset), kInfinity) ? 0 : 1);
            }
            if (!is_black(T)) {
                const Real pdf_env = cosine_hemisphere_pdf(cos_i);
                const Real w = mis ? power_heuristic(pdf_env, bsdf.pdf(wo, wi, n)) : Real(1);
                sum += f * T * environment_->radiance * (cos_i * w / pdf_env);
            }
        }
    }
    return sum;
}

Color PathTracer::radiance(const Ray& camera_ray, SampleStream rng, RayCounts& rays, PathFeatures* features,
                           PathParts* parts) const {
    // EXERCISE(ch06.path_tracer) § The path tracer
    const SamplingStrategy strategy = options_.strategy;
    const bool direct = options_.simulates(Effect::kDirect);
    const bool indirect = options_.simulates(Effect::kIndirect);
    const bool nee = direct && samples_lights(strategy);
    const bool mis = strategy == SamplingStrategy::kMis;
    Color L(0), beta(1);
    Ray ray = camera_ray;
    bool specular = true;   // the camera ray, or a delta bounce: what it hits counts in full
    Real previous_pdf = 0;  // the BSDF-sampling density of the ray's direction, for MIS
    Vec3 previous_point(0), previous_normal(0);  // normal 0: the previous vertex was in a medium
    int bounces = 0;                             // non-delta bounces so far
    Real eta_scale = 1;  // Π η² of the refractions so far: β × eta_scale is what Russian roulette judges
    Real length = 0;                             // of the path so far, for `features`
    bool clear_so_far = true;  // no delta bounce (and no medium event) yet: the path is E D*
    // Chapter 09's media: the events of the path's walks so far (scattering, and reflections at a walk's
    // boundary), the colour channel whose density draws its free flights (chosen when the path first meets a
    // medium that scatters), and the densities of the path under each channel's sampling, relative to the
    // chosen one's and kept at mean 1 (spectral MIS over the whole path: β is divided by their mean).
    int medium_events = 0;
    int channel = -1;
    Color spectral_pdf(1);
    // The analysis hook (path_parts.hpp): the kind of path by which the light L just gained arrived.
    const auto file_light_met = [&] {
        if (!parts) return;
        parts->file(!specular ? PathPart::kBsdfHit : bounces == 0 ? PathPart::kSeen : PathPart::kCaustic, L);
    };
    for (int depth = 0;;) {
        const auto hit = world_.intersect(ray);
        // The segment runs through what fills the space it crosses, if anything: a medium that only absorbs
        // attenuates it (chapter 07); one that scatters may end it early at a scattering event (chapter 09).
        if (const Medium* medium = medium_along(hit)) {
            if (channel < 0 && medium->phase()) channel = pick_channel(rng.next_real());
            const FreeFlight flight =
                medium->sample_free_flight(hit ? hit->t : kInfinity, channel, rng.generator());
            beta *= flight.weight;
            if (flight.pdf_ratio != Color(1)) {
                spectral_pdf *= flight.pdf_ratio;
                const Real mean = (spectral_pdf.r + spectral_pdf.g + spectral_pdf.b) / 3;
                beta /= mean;
                spectral_pdf /= mean;
            }
            if (flight.scattered) {
                // A vertex in the volume at p: the phase function in the place of a BSDF, no surface.
                if ((!indirect && bounces >= 1) || ++medium_events > options_.walk.max_events) break;
                const PhaseFunction& phase = *medium->phase();
                const Vec3 p = ray.at(flight.t);
                const Vec3 wo = -ray.direction;
                if (nee) L += beta * next_event_in_medium(p, wo, phase, rng, rays);
                if (parts) parts->file(PathPart::kNextEvent, L);
                const PhaseSample s = phase.sample(wo, rng.next_vec2());
                if (!(s.pdf > 0) || !(s.p > 0)) break;
                beta *= s.p / s.pdf;
                ++bounces;
                specular = false;
                previous_pdf = s.pdf;
                previous_point = p;
                previous_normal = Vec3(0);
                clear_so_far = false;
                if (options_.walk.roulette) {
                    const Real q = std::min(Real(1), std::max({beta.r, beta.g, beta.b}));
                    if (!(rng.next_real() < q)) break;
                    beta /= q;
                }
                ray = Ray{p, s.wi};
                rays.add(RayKind::kIndirect);
                continue;
            }
        }
        // Light the path meets: counted in full without next-event estimation, weighted by MIS with it, and
        // not at all by the light strategy (its next-event estimate already counted it).
        if (!hit) {
            if (environment_ && (specular || direct)) {
                Real w = 1;
                if (!specular && nee) {
                    // What next_event (cosine-weighted about the normal) or next_event_in_medium (uniform
                    // over the sphere) would have drawn this direction with.
                    const Real pdf_light =
                        previous_normal == Vec3(0)
                            ? kUniformSpherePdf
                            : cosine_hemisphere_pdf(glm::dot(ray.direction, previous_normal));
                    w = mis ? power_heuristic(previous_pdf, pdf_light) : Real(0);
                }
                L += beta * environment_->radiance * w;
                file_light_met();
            }
            break;
        }
        const Color emitted = materials_.emission(hit->material, hit->front_face);
        if (!is_black(emitted) && (specular || direct)) {
            Real w = 1;
            // The hit knows its light. An emissive plane is none (Hit::light = −1): next-event estimation
            // cannot sample it (no finite area), so only a path that hits it sees it, whatever the strategy.
            if (!specular && nee && hit->light >= 0) {
                w = mis ? power_heuristic(previous_pdf, picker_.pdf(previous_point, ray.direction, *hit))
                        : Real(0);
            }
            L += beta * emitted * w;
            file_light_met();
        }
        if (!indirect && bounces >= 1) break;
        const Bsdf& bsdf = materials_.bsdf(hit->material, hit->front_face);
        const BsdfFlags& flags = bsdf.flags();
        length += hit->t;
        // With media, shadow rays cross an index-matched boundary (transmittance()), so light sampling sees
        // what lies beyond it: a path crossing one makes no vertex there and goes straight on.
        if (media_ && flags.index_matched) {
            ray = spawn_ray(*hit, ray.direction, options_.offset);
            rays.add(RayKind::kRefraction);
            continue;
        }
        // E D{1..K} S: the rest of this path is the light tracer's (PathOptions::camera_caustic_bounces).
        if (flags.delta && clear_so_far && bounces >= 1 && bounces <= options_.camera_caustic_bounces) break;
        const bool records = features && !features->recorded && !flags.delta;
        // Chapter 10's features, at the first vertex that is not a delta bounce (the albedo once the bounce
        // is drawn).
        if (records) *features = {Color(0), hit->normal, length, true};
        if (flags.black) break;
        const Vec3 wo = -ray.direction;
        const Vec3& n = hit->normal;
        if (nee && !flags.delta) L += beta * next_event(*hit, wo, bsdf, rng, rays);
        if (parts) parts->file(PathPart::kNextEvent, L);
        // Without the indirect effect the path ends at the vertex it reaches next, where light sampling alone
        // (no MIS) already counted every light it could meet — unless some emitter cannot be sampled.
        if (!indirect && !flags.delta && nee && !mis && !has_unsampled_emitters_) break;

        // The direction that continues the path, and its density.
        BsdfSample s;
        const Vec2 u = rng.next_vec2();
        if (flags.delta || strategy == SamplingStrategy::kBrdf || nee) {
            // A BSDF with two lobes (reflection and transmission) takes one more number to choose between
            // them.
            s = bsdf.sample(wo, n, u, flags.transmission ? rng.next_real() : Real(0));
        } else {
            const bool uniform = strategy == SamplingStrategy::kUniform;
            const Vec3 local = uniform ? sample_uniform_hemisphere(u) : sample_cosine_hemisphere(u);
            s.wi = glm::normalize(make_frame(n).to_world(local));
            s.pdf = uniform ? uniform_hemisphere_pdf(local) : cosine_hemisphere_pdf(local.z);
            s.f = bsdf.eval(wo, s.wi, n);
        }
        const Real cos_i = scattering_cosine(s.wi, n, s.transmitted);
        if (!(cos_i > 0) || !(s.pdf > 0) || is_black(s.f)) break;
        if (records) features->albedo = beta * s.f * (cos_i / s.pdf);
        beta *= s.f * (cos_i / s.pdf);
        if (options_.roulette_eta_scale) eta_scale /= s.radiance_scale;
        if (flags.delta) clear_so_far = false;
        if (!flags.delta) ++bounces;
        specular = flags.delta;
        previous_pdf = flags.delta ? kInfinity : s.pdf;
        previous_point = hit->point;
        previous_normal = n;
        // A walk's own boundary met from inside (a medium that scatters fills this side): its reflections and
        // refractions belong to the walk, which ends by the walk's rules, not by the bounces of
        // `termination`.
        const Medium* inside = hit->front_face ? nullptr : materials_.interior(hit->material);
        if (inside && inside->phase()) {
            if (++medium_events > options_.walk.max_events) break;
        } else if (!continue_path(options_.termination, ++depth, beta, rng.next_real(), eta_scale)) {
            break;
        }
        ray = spawn_ray(*hit, s.wi, options_.offset);
        rays.add(ray_kind(flags, s.transmitted));
    }
    return L;
    // END EXERCISE
}

RenderResult render_paths(const PathTracer& tracer, const PinholeCamera& camera,
                          const RenderSettings& settings) {
    const PointSet points = tracer.options().sampler;
    if (points != PointSet::kSobol) {
        return render_camera_rays(
            camera, points == PointSet::kStratified ? PixelSampler::kStratified : PixelSampler::kUniform,
            settings,
            [&](const Ray& ray, Pcg32& rng, RayCounts& rays) { return tracer.radiance(ray, rng, rays); });
    }
    // Sobol: the pixel's sequence, point s.index of it; its first two dimensions place the camera ray.
    const int count = settings.samples_per_pixel;
    const auto width = std::uint64_t(settings.width);
    return render(settings, [&](const PixelSample& s, Pcg32& rng, RayCounts& rays) {
        OwenSobolStream sobol(std::uint64_t(s.y) * width + std::uint64_t(s.x), std::uint32_t(s.index),
                              settings.seed);
        const Ray ray = camera_ray_of(camera, PixelSampler::kUniform, s, count, sobol.next_vec2(), rays);
        return finite_or_black(tracer.radiance(ray, SampleStream(sobol, rng), rays));
    });
}

}  // namespace rt
