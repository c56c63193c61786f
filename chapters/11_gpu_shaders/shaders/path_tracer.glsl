// Chapter 06's path loop (PathTracer::radiance) with multiple importance sampling, as chapter 07 renders
// with it: next-event estimation (one light picked by power, and the environment) weighted by the power
// heuristic against BSDF sampling, chapter 05's Russian roulette from bounce 8 under a cap of 64 bounces,
// chapter 07's smooth dielectric and Beer–Lambert interiors. The same random numbers are drawn in the same
// order as on the CPU, so one (pixel, sample) follows the same path on both up to rounding.

uniform bool simulate_direct;    // Effect::kDirect
uniform bool simulate_indirect;  // Effect::kIndirect
uniform bool simulate_shadows;   // Effect::kShadows
uniform int max_depth;           // the cap on bounces: the scene's max_depth, else chapter 06's 64

// The camera (chapter 01's PinholeCamera) and the film.
uniform vec3 camera_eye;
uniform vec3 camera_forward;
uniform vec3 camera_right;
uniform vec3 camera_up;
uniform vec2 camera_half_size;  // (half_width, half_height)
uniform float camera_lens_radius;     // chapter 01's thin lens: the aperture, 0 for the pinhole
uniform float camera_focus_distance;  // along camera_forward
uniform ivec2 image_size;
uniform int strata;         // ⌊√spp⌋: chapter 01's stratified pixel sampler
uniform int spp;            // of the whole render
uniform uvec2 seed_bits;    // the 64-bit seed, low and high words
// The lesson's divergence experiment (ch11_benchmark): every pixel draws pixel 0's random numbers, so the
// paths of neighbouring pixels bounce alike and a SIMD group stays together. Its image is blotchy (the
// pixels' errors are correlated): for timing only.
uniform bool shared_streams;

// Rays by kind, RayKind's order: camera, shadow, reflection, refraction, indirect; each invocation adds its
// own counts once.
layout(std430, binding = 4) buffer RayCounters { uint ray_counters[5]; };
uint rays_traced[5] = uint[5](0u, 0u, 0u, 0u, 0u);
const int kCameraRay = 0, kShadowRay = 1, kReflectionRay = 2, kRefractionRay = 3, kIndirectRay = 4;

// Chapter 06's mis_weight with β = 2: p_a² / (p_a² + p_b²), with its edge cases (∞ is a delta).
float power_heuristic(float a, float b) {
    if (a == b) return 0.5;
    if (isinf(a)) return 1.0;
    if (isinf(b)) return 0.0;
    if (!(a > 0.0)) return 0.0;
    if (!(b > 0.0)) return 1.0;
    const float r = b / a;
    return 1.0 / (1.0 + r * r);
}

bool visible(Hit hit, vec3 target) {
    float t_max;
    const Ray shadow = spawn_shadow_ray(hit, target, t_max);
    ++rays_traced[kShadowRay];
    return !occluded(shadow, t_max);
}

// PathTracer::next_event: one light picked by power (weighted for MIS when it has a surface) and the
// environment (one cosine-weighted direction).
vec3 next_event(Hit hit, vec3 wo, Material m, inout Pcg32 rng) {
    const bool both_sides = transmits(m);
    const vec3 n = hit.normal;
    vec3 sum = vec3(0.0);
    if (light_count > 0u) {
        const float u_pick = light_count > 1u ? pcg_next_real(rng) : 0.0;  // one light: nothing to choose
        const vec2 u = pcg_next_vec2(rng);
        LightSample s;
        if (sample_light(hit.point, u_pick, u, s)) {
            const float dot_i = dot(s.wi, n);
            const float cos_i = both_sides ? abs(dot_i) : dot_i;
            if (cos_i > 0.0 && s.pdf > 0.0) {
                const vec3 f = bsdf_eval(m, wo, s.wi, n);
                if (any(greaterThan(f, vec3(0.0))) && (!simulate_shadows || visible(hit, s.point))) {
                    const float w = s.on_surface ? power_heuristic(s.pdf, bsdf_pdf(m, wo, s.wi, n)) : 1.0;
                    sum += f * s.radiance * (cos_i * w / s.pdf);
                }
            }
        }
    }
    if (has_environment) {
        const vec3 wi = normalize(to_world(make_frame(n), sample_cosine_hemisphere(pcg_next_vec2(rng))));
        const float cos_i = dot(wi, n);
        const vec3 f = cos_i > 0.0 ? bsdf_eval(m, wo, wi, n) : vec3(0.0);
        if (any(greaterThan(f, vec3(0.0)))) {
            bool seen = true;
            if (simulate_shadows) {
                ++rays_traced[kShadowRay];
                seen = !occluded(spawn_ray(hit, wi), kInfinity);
            }
            if (seen) {
                const float pdf_env = cosine_hemisphere_pdf(cos_i);
                sum += f * environment_radiance * (cos_i * power_heuristic(pdf_env, bsdf_pdf(m, wo, wi, n)) / pdf_env);
            }
        }
    }
    return sum;
}

// Chapter 05's continue_path with Russian roulette: q = min(1, max β η-scale) from kRouletteStart, 0 at bounce
// max_depth (chapter 06's loop judges β with refraction's 1/η² divided out: eta_scale = Π η²).
const int kRouletteStart = 8;  // chapter 06's kPathRouletteStart
bool continue_path(int depth, inout vec3 beta, float u, float eta_scale) {
    float q = 0.0;
    const vec3 judged = beta * eta_scale;
    const float largest = max(max(judged.r, judged.g), judged.b);
    if (depth < max_depth && all_finite(judged) && largest > 0.0)
        q = depth < kRouletteStart ? 1.0 : min(1.0, largest);
    if (!(u < q)) return false;
    if (q < 1.0) beta /= q;
    return true;
}

vec3 radiance(Ray ray, inout Pcg32 rng) {
    const bool nee = simulate_direct;
    vec3 L = vec3(0.0), beta = vec3(1.0);
    bool specular = true;
    float previous_pdf = 0.0;
    vec3 previous_point = vec3(0.0), previous_normal = vec3(0.0);
    int bounces = 0;
    float eta_scale = 1.0;
    bool last_ray = false;  // chapter 06's: the ray drawn at the depth cap adds the light it meets, no more
    for (int depth = 0;; ++depth) {
        Hit hit;
        if (!intersect_scene(ray, kInfinity, hit)) {
            if (has_environment && (specular || simulate_direct)) {
                float w = 1.0;
                if (!specular && nee)
                    w = power_heuristic(previous_pdf, cosine_hemisphere_pdf(dot(ray.direction, previous_normal)));
                L += beta * environment_radiance * w;
            }
            break;
        }
        const Material m = materials[hit.material];
        if (!hit.front_face && m.info.z != 0u) beta *= transmittance(m, hit.t);
        const vec3 emitted = hit.front_face ? m.emission.rgb : vec3(0.0);
        if (any(greaterThan(emitted, vec3(0.0))) && (specular || simulate_direct)) {
            float w = 1.0;
            if (!specular && nee && hit.light != kNoLight)
                w = power_heuristic(previous_pdf, light_pdf(previous_point, ray.direction, hit));
            L += beta * emitted * w;
        }
        if (last_ray) break;
        if (!simulate_indirect && bounces >= 1) break;
        if (m.info.y != 0u) break;  // black: it scatters nothing
        const bool delta = is_delta(m);
        const vec3 wo = -ray.direction;
        const vec3 n = hit.normal;
        if (nee && !delta) L += beta * next_event(hit, wo, m, rng);

        BsdfSample s;
        const vec2 u = pcg_next_vec2(rng);
        if (delta || nee) {
            s = bsdf_sample(m, hit.front_face, wo, n, u, transmits(m) ? pcg_next_real(rng) : 0.0);
        } else {
            // Without direct light, MIS has no light sampler: cosine-weighted directions.
            const vec3 local = sample_cosine_hemisphere(u);
            s.wi = normalize(to_world(make_frame(n), local));
            s.pdf = cosine_hemisphere_pdf(local.z);
            s.f = bsdf_eval(m, wo, s.wi, n);
            s.transmitted = false;
        }
        const float cos_i = s.transmitted ? -dot(s.wi, n) : dot(s.wi, n);
        if (!(cos_i > 0.0) || !(s.pdf > 0.0) || !any(greaterThan(s.f, vec3(0.0)))) break;
        beta *= s.f * (cos_i / s.pdf);
        if (s.transmitted) {
            // As the CPU's loop: divided by the radiance scale 1/η² the dielectric's sample holds.
            const float eta = hit.front_face ? m.eta.x : m.eta.y;
            eta_scale /= 1.0 / (eta * eta);
        }
        if (!delta) ++bounces;
        specular = delta;
        previous_pdf = delta ? kInfinity : s.pdf;
        previous_point = hit.point;
        previous_normal = n;
        // Chapter 06's roulette step: a number is drawn only from kRouletteStart, where roulette starts.
        if (!continue_path(depth + 1, beta, depth + 1 >= kRouletteStart ? pcg_next_real(rng) : 0.0, eta_scale)) {
            // At the cap, light met by the drawn ray still counts where MIS or a delta bounce weighs it.
            if (depth + 1 < max_depth || !(specular || simulate_direct)) break;
            last_ray = true;
        }
        ray = spawn_ray(hit, s.wi);
        ++rays_traced[s.transmitted ? kRefractionRay : is_diffuse(m) ? kIndirectRay : kReflectionRay];
    }
    return L;
}

// Chapter 01's stratified film point of sample `index` in pixel (x, y), kept inside the pixel.
vec2 pixel_sample_point(ivec2 pixel, int index, vec2 u) {
    const vec2 corner = vec2(pixel);
    const vec2 last = vec2(next_float_down(corner.x + 1.0), next_float_down(corner.y + 1.0));
    if (index >= strata * strata) return min(corner + u, last);
    const vec2 stratum = vec2(float(index % strata), float(index / strata));
    return min(corner + (stratum + u) / float(strata), last);
}

// Chapter 01's concentric map (Shirley and Chiu 1997): u in [0, 1)² onto the unit disk, uniformly.
vec2 sample_disk_concentric(vec2 u) {
    const vec2 ab = 2.0 * u - 1.0;
    if (ab.x == 0.0 && ab.y == 0.0) return vec2(0.0);
    float r, phi;
    if (abs(ab.x) > abs(ab.y)) {
        r = ab.x;
        phi = (kPi / 4.0) * (ab.y / ab.x);
    } else {
        r = ab.y;
        phi = kPi / 2.0 - (kPi / 4.0) * (ab.x / ab.y);
    }
    return r * vec2(cos(phi), sin(phi));
}

// One sample of pixel (x, y): the camera ray through its film point, what it sees, and nothing non-finite.
vec3 render_sample(ivec2 pixel, int index) {
    const uint64_t number = uint64_t(pixel.y) * uint64_t(image_size.x) + uint64_t(pixel.x);
    Pcg32 rng = pcg_for_sample(shared_streams ? 0UL : number, uint64_t(index), packUint2x32(seed_bits));
    const vec2 film = pixel_sample_point(pixel, index, pcg_next_vec2(rng));
    ++rays_traced[kCameraRay];
    const float a = (2.0 * film.x / float(image_size.x) - 1.0) * camera_half_size.x;
    const float b = (1.0 - 2.0 * film.y / float(image_size.y)) * camera_half_size.y;
    const vec3 d = camera_forward + a * camera_right + b * camera_up;
    Ray ray = Ray(camera_eye, normalize(d));
    if (camera_lens_radius > 0.0) {
        // Chapter 01's thin lens: from a point of the lens through d's point on the plane in focus. A pinhole
        // draws nothing more, as on the CPU.
        const vec2 lens = camera_lens_radius * sample_disk_concentric(pcg_next_vec2(rng));
        const vec3 origin = camera_eye + lens.x * camera_right + lens.y * camera_up;
        ray = Ray(origin, normalize(camera_eye + camera_focus_distance * d - origin));
    }
    const vec3 L = radiance(ray, rng);
    return all_finite(L) ? L : vec3(0.0);
}

// Adds this invocation's ray counts into the totals: one atomic per kind, not one per ray.
void flush_ray_counts() {
    for (int k = 0; k < 5; ++k)
        if (rays_traced[k] > 0u) atomicAdd(ray_counters[k], rays_traced[k]);
}
