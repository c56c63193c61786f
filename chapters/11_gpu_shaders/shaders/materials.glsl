// The material table on the GPU (gpu_scene.cpp flattens chapter 04's MaterialTable): chapter 04's four
// BRDFs and chapter 07's smooth dielectric and Beer–Lambert interior. The CPU calls them through a virtual
// function; a GPU has no such jump, so the shader switches on the kind the flattening wrote. Directions point
// away from the surface; n is the unit normal on wo's side.

const uint kLambert = 0u, kMirror = 1u, kGlossy = 2u, kRetroreflective = 3u, kSmoothDielectric = 4u;

// info = (kind, black, has_interior, unused); color = albedo or reflectance (w: Phong exponent);
// eta = (η seen from outside, η seen from inside, unused, unused); absorption = σ_a of the interior.
struct Material {
    uvec4 info;
    vec4 color;
    vec4 eta;
    vec4 emission;
    vec4 absorption;
};
layout(std430, binding = 2) readonly buffer Materials { Material materials[]; };

bool is_delta(Material m) { return m.info.x == kMirror || m.info.x == kSmoothDielectric; }
bool transmits(Material m) { return m.info.x == kSmoothDielectric; }
bool is_diffuse(Material m) { return m.info.x == kLambert; }

// ---- chapter 04's frame.hpp (Duff et al. 2017) and sampling.cpp ----
struct Frame {
    vec3 t;
    vec3 b;
    vec3 n;
};

Frame make_frame(vec3 n) {
    const float s = n.z < 0.0 || (n.z == 0.0 && floatBitsToUint(n.z) != 0u) ? -1.0 : 1.0;
    const float a = -1.0 / (s + n.z);
    const float c = n.x * n.y * a;
    return Frame(vec3(1.0 + s * n.x * n.x * a, s * c, -s * n.x), vec3(c, s + n.y * n.y * a, -n.y), n);
}

vec3 to_world(Frame f, vec3 local) { return local.x * f.t + local.y * f.b + local.z * f.n; }

vec3 spherical(float cos_theta, float sin_theta, float u) {
    const float phi = 2.0 * kPi * u;
    return vec3(sin_theta * cos(phi), sin_theta * sin(phi), cos_theta);
}

vec3 sample_cosine_hemisphere(vec2 u) {
    return spherical(sqrt(max(0.0, 1.0 - u.x)), sqrt(u.x), u.y);
}

float cosine_hemisphere_pdf(float cos_theta) { return max(0.0, cos_theta) * kInvPi; }

vec3 sample_uniform_cone(vec2 u, float one_minus_cos_max) {
    const float one_minus_cos = u.x * one_minus_cos_max;
    return spherical(1.0 - one_minus_cos, sqrt(max(0.0, one_minus_cos * (2.0 - one_minus_cos))), u.y);
}

// log1p and expm1, which GLSL lacks, by Kahan's and Higham's corrections: exact to a few ulps near 0.
float log1p_accurate(float x) {
    const float u = 1.0 + x;
    return u == 1.0 ? x : log(u) * x / (u - 1.0);
}
float expm1_accurate(float x) {
    const float u = exp(x);
    if (u == 1.0) return x;
    const float um1 = u - 1.0;
    return um1 == -1.0 ? -1.0 : um1 * x / log(u);
}

vec3 sample_power_cosine(vec2 u, float exponent) {
    const float one_minus_cos = -expm1_accurate(log1p_accurate(-u.x) / (exponent + 1.0));
    return spherical(1.0 - one_minus_cos, sqrt(max(0.0, one_minus_cos * (2.0 - one_minus_cos))), u.y);
}

float power_cosine_pdf(float cos_alpha, float exponent) {
    if (!(cos_alpha > 0.0)) return 0.0;
    return (exponent + 1.0) * 0.5 * kInvPi * pow(min(1.0, cos_alpha), exponent);
}

vec3 reflect_about(vec3 w, vec3 n) { return 2.0 * dot(n, w) * n - w; }

// ---- chapter 07's Fresnel and Snell ----
const float kTirCos2 = 4.0 * 1.1920928955078125e-7;

float cos2_transmitted(float cos_i, float eta) {
    const float c = clamp(cos_i, 0.0, 1.0);
    return max(0.0, 1.0 - (1.0 - c * c) / (eta * eta));
}

float fresnel_dielectric(float cos_i, float eta) {
    if (cos_i < 0.0) {
        cos_i = -cos_i;
        eta = 1.0 / eta;
    }
    cos_i = min(cos_i, 1.0);
    const float cos2_t = cos2_transmitted(cos_i, eta);
    if (cos2_t <= kTirCos2) return 1.0;
    const float ct = sqrt(cos2_t);
    const float r_par = (eta * cos_i - ct) / (eta * cos_i + ct);
    const float r_perp = (cos_i - eta * ct) / (cos_i + eta * ct);
    return min(1.0, (r_par * r_par + r_perp * r_perp) / 2.0);
}

// The refracted direction, false under total internal reflection.
bool refract_through(vec3 wo, vec3 n, float eta, out vec3 wt) {
    wt = vec3(0.0);
    float cos_i = dot(n, wo);
    const vec3 normal = cos_i < 0.0 ? -n : n;
    if (cos_i < 0.0) {
        cos_i = -cos_i;
        eta = 1.0 / eta;
    }
    cos_i = min(cos_i, 1.0);
    const float cos2_t = cos2_transmitted(cos_i, eta);
    if (cos2_t <= kTirCos2) return false;
    wt = normalize(-wo / eta + (cos_i / eta - sqrt(cos2_t)) * normal);
    return true;
}

// ---- the BSDF of a material, from one side ----
bool above(vec3 wo, vec3 wi, vec3 n) { return dot(wo, n) > 0.0 && dot(wi, n) > 0.0; }

// Chapter 04's normalized lobe f ∝ ρ cos^e α around `axis` (lobe_eval).
vec3 lobe_eval(vec3 albedo, float exponent, vec3 axis, vec3 wo, vec3 wi, vec3 n) {
    if (!above(wo, wi, n)) return vec3(0.0);
    const float c = min(1.0, dot(wi, axis));
    const float power = c > 0.0 ? pow(c, exponent) : 0.0;
    return albedo * ((exponent + 2.0) * 0.5 * kInvPi * power);
}

vec3 lobe_axis(Material m, vec3 wo, vec3 n) { return m.info.x == kGlossy ? reflect_about(wo, n) : wo; }

vec3 bsdf_eval(Material m, vec3 wo, vec3 wi, vec3 n) {
    if (m.info.x == kLambert) return above(wo, wi, n) ? m.color.rgb * kInvPi : vec3(0.0);
    if (m.info.x == kGlossy || m.info.x == kRetroreflective)
        return lobe_eval(m.color.rgb, m.color.w, lobe_axis(m, wo, n), wo, wi, n);
    return vec3(0.0);  // delta lobes
}

float bsdf_pdf(Material m, vec3 wo, vec3 wi, vec3 n) {
    if (m.info.x == kLambert) return cosine_hemisphere_pdf(dot(wi, n));
    if (m.info.x == kGlossy || m.info.x == kRetroreflective)
        return power_cosine_pdf(dot(wi, lobe_axis(m, wo, n)), m.color.w);
    return 0.0;
}

struct BsdfSample {
    vec3 wi;
    vec3 f;
    float pdf;
    bool transmitted;
};

BsdfSample bsdf_sample(Material m, bool front_face, vec3 wo, vec3 n, vec2 u, float u_lobe) {
    BsdfSample s = BsdfSample(vec3(0.0, 0.0, 1.0), vec3(0.0), 0.0, false);
    if (m.info.x == kLambert) {
        s.wi = normalize(to_world(make_frame(n), sample_cosine_hemisphere(u)));
        s.f = above(wo, s.wi, n) ? m.color.rgb * kInvPi : vec3(0.0);
        s.pdf = cosine_hemisphere_pdf(dot(s.wi, n));
    } else if (m.info.x == kMirror) {
        s.wi = reflect_about(wo, n);
        const float cos_i = dot(s.wi, n);
        s.f = cos_i > 0.0 ? m.color.rgb / cos_i : vec3(0.0);
        s.pdf = 1.0;
    } else if (m.info.x == kGlossy || m.info.x == kRetroreflective) {
        const vec3 axis = lobe_axis(m, wo, n);
        s.wi = normalize(to_world(make_frame(axis), sample_power_cosine(u, m.color.w)));
        s.f = lobe_eval(m.color.rgb, m.color.w, axis, wo, s.wi, n);
        s.pdf = power_cosine_pdf(dot(s.wi, axis), m.color.w);
    } else {
        // Chapter 07's sample_dielectric: reflection with probability R, else refraction, weight 1 / η².
        const float eta = front_face ? m.eta.x : m.eta.y;
        const float R = fresnel_dielectric(dot(n, wo), eta);
        vec3 weight = vec3(1.0);
        vec3 wt;
        if (u_lobe >= R && refract_through(wo, n, eta, wt)) {
            s.wi = wt;
            s.transmitted = true;
            weight = vec3(1.0 / (eta * eta));
        } else {
            s.wi = normalize(reflect_about(wo, n));
        }
        s.pdf = 1.0;
        const float cos_i = abs(dot(s.wi, n));
        s.f = cos_i > 0.0 ? weight / cos_i : vec3(0.0);
    }
    return s;
}

// Beer–Lambert inside the material's shapes: exp(−σ_a d) per channel, exactly 1 where σ_a = 0.
vec3 transmittance(Material m, float distance) {
    vec3 t = vec3(1.0);
    for (int c = 0; c < 3; ++c)
        if (m.absorption[c] > 0.0) t[c] = exp(-m.absorption[c] * distance);
    return t;
}
