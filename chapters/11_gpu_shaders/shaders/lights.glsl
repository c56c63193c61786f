// Chapter 04's LightPicker on the GPU: one light picked by power from the running sums of P(light) (the
// same cdf), then a point on it: quads and triangles by area, spheres by solid angle, point, distant and
// spot lights as deltas. The lights are in the picker's order: quads, triangles, spheres, points, distant
// lights, spots.

const uint kQuadLight = 0u, kTriangleLight = 1u, kSphereLight = 2u, kPointLight = 3u, kDistantLight = 4u,
           kSpotLight = 5u;

// info.x = kind; a, b, c by kind: quad origin, u, v; triangle p0, p1, p2; sphere (centre, radius); point
// position; distant (−direction), (scene centre, scene radius); spot position, (axis, cos θ_end),
// (cos θ_start). normal = (unit normal, P(light)), radiance = (L, I or E, cdf), c.w = area.
struct Light {
    uvec4 info;
    vec4 a;
    vec4 b;
    vec4 c;
    vec4 normal;
    vec4 radiance;
};
layout(std430, binding = 3) readonly buffer Lights { Light lights[]; };

uniform uint light_count;     // 0 when no light emits any power
uniform float light_total;    // Σ Φ / π (LightPicker::total_weight)
uniform bool has_environment;
uniform vec3 environment_radiance;

struct LightSample {
    vec3 point;
    vec3 wi;
    vec3 radiance;
    float pdf;
    bool on_surface;
};

float luminance(vec3 c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

// The first light whose cdf exceeds u (std::upper_bound), the last at most.
uint pick_light(float u) {
    uint first = 0u, count = light_count;
    while (count > 0u) {
        const uint step = count / 2u;
        if (!(u < lights[first + step].radiance.w)) {
            first += step + 1u;
            count -= step + 1u;
        } else {
            count = step;
        }
    }
    return min(first, light_count - 1u);
}

// Toward x on a one-sided planar light of unit normal n and area A: pdf = d² / (cos θ_l A).
bool toward_planar(vec3 x, vec3 n, float area, vec3 radiance, vec3 p, out LightSample s) {
    s = LightSample(x, vec3(0.0, 0.0, 1.0), radiance, 0.0, true);
    const vec3 to_light = x - p;
    const float distance = length(to_light);
    if (!(distance > 0.0)) return false;
    s.wi = to_light / distance;
    const float cos_light = -dot(n, s.wi);
    if (!(cos_light > 0.0)) return false;
    s.pdf = distance * distance / (cos_light * area);
    return !isinf(s.pdf) && !isnan(s.pdf);
}

float one_minus_cos_stable(float sin2_max) {
    return sin2_max / (1.0 + sqrt(max(0.0, 1.0 - sin2_max)));
}

bool sample_sphere_light(Light light, vec3 p, vec2 u, out LightSample s) {
    s = LightSample(vec3(0.0), vec3(0.0, 0.0, 1.0), light.radiance.rgb, 0.0, true);
    const vec3 centre = light.a.xyz;
    const float r = light.a.w;
    const vec3 to_centre = centre - p;
    const float d = length(to_centre);
    if (!(d > r)) return false;
    const float ratio = r / d;
    const float one_minus_cos_max = one_minus_cos_stable(ratio * ratio);
    const vec3 local = sample_uniform_cone(u, one_minus_cos_max);
    s.wi = normalize(to_world(make_frame(to_centre / d), local));
    const float cos_theta = min(1.0, local.z);
    const float d_sin = d * sqrt(local.x * local.x + local.y * local.y);
    const float root = sqrt(max(0.0, (r - d_sin) * (r + d_sin)));
    const float t = (d - r) * (d + r) / (d * cos_theta + root);
    s.pdf = 1.0 / (2.0 * kPi * one_minus_cos_max);
    s.point = centre + r * normalize(p + t * s.wi - centre);
    return true;
}

// LightPicker::sample: a light chosen by u_pick, a point on it from u; the pdf includes P(light).
bool sample_light(vec3 p, float u_pick, vec2 u, out LightSample s) {
    const uint i = pick_light(u_pick);
    const Light light = lights[i];
    const float P = light.normal.w;
    s = LightSample(vec3(0.0), vec3(0.0, 0.0, 1.0), vec3(0.0), 0.0, false);
    if (!(P > 0.0)) return false;
    bool found = false;
    if (light.info.x == kQuadLight) {
        found = toward_planar(light.a.xyz + u.x * light.b.xyz + u.y * light.c.xyz, light.normal.xyz, light.c.w,
                              light.radiance.rgb, p, s);
    } else if (light.info.x == kTriangleLight) {
        const float root = sqrt(u.x);
        const vec2 b = vec2(1.0 - root, u.y * root);
        const vec3 x = (1.0 - b.x - b.y) * light.a.xyz + b.x * light.b.xyz + b.y * light.c.xyz;
        found = toward_planar(x, light.normal.xyz, light.c.w, light.radiance.rgb, p, s);
    } else if (light.info.x == kSphereLight) {
        found = sample_sphere_light(light, p, u, s);
    } else if (light.info.x == kDistantLight) {
        // DistantEmitter::sample: the shadow ray ends past every shape.
        const float reach = max(1.0, length(p - light.b.xyz) + 2.0 * light.b.w);
        s = LightSample(p + reach * light.a.xyz, light.a.xyz, light.radiance.rgb, 1.0, false);
        found = true;
    } else {
        const vec3 to_light = light.a.xyz - p;
        const float d2 = dot(to_light, to_light);
        if (d2 > 0.0) {
            s = LightSample(light.a.xyz, to_light / sqrt(d2), light.radiance.rgb / d2, 1.0, false);
            found = true;
        }
        if (found && light.info.x == kSpotLight) {
            // SpotEmitter::falloff toward p: smoothstep in cos θ from cos θ_end to cos θ_start.
            const float c = dot(light.b.xyz, -s.wi), cos_end = light.b.w, cos_start = light.c.x;
            float falloff = c < cos_end ? 0.0 : 1.0;
            if (cos_start > cos_end) {
                const float t = clamp((c - cos_end) / (cos_start - cos_end), 0.0, 1.0);
                falloff = t * t * (3.0 - 2.0 * t);
            }
            s.radiance *= falloff;
            found = falloff > 0.0;
        }
    }
    if (found) s.pdf *= P;
    return found;
}

// LightPicker::pdf: the density with which sample_light draws wi from p when p + t wi first meets the light
// of `hit`.
float light_pdf(vec3 p, vec3 wi, Hit hit) {
    if (light_count == 0u || hit.light == kNoLight) return 0.0;
    const Light light = lights[hit.light];
    if (light.info.x == kSphereLight) {
        const float d = length(light.a.xyz - p);
        if (!(d > light.a.w)) return 0.0;
        const float ratio = light.a.w / d;
        return light.normal.w / (2.0 * kPi * one_minus_cos_stable(ratio * ratio));
    }
    const float cos_light = -dot(hit.normal, wi);
    if (!(cos_light > 0.0)) return 0.0;
    return luminance(light.radiance.rgb) * hit.t * hit.t / (cos_light * light_total);
}
