// The scene as the GPU reads it: chapter 02's BVH, the primitives, the materials and the lights, each one
// shader storage buffer (std430) written by gpu_scene.cpp. The intersection code is chapter 02's, line for
// line: the slab test, the stable sphere quadratic, the quad's dual basis, the watertight triangle, the
// plane; then chapter 02's traversal (nearest box first, a stack of 64) and its hit record with the rounding
// bound chapter 03's robust offset reads.

// +∞ by its bits (GLSL has no infinite literal, and a function call is no constant expression for a const).
#define kInfinity uintBitsToFloat(0x7F800000u)
const float kPi = 3.14159265358979323846;
const float kInvPi = 0.318309886183790671538;

// γ_n = n u / (1 − n u), u = 2^-24 (chapter 02's float_error.hpp).
float gamma_bound(int n) {
    const float u = 1.0 / 16777216.0;
    return float(n) * u / (1.0 - float(n) * u);
}

// std::nextafter(x, ±∞) for finite x.
float next_float_up(float x) {
    if (x == 0.0) return uintBitsToFloat(1u);
    const uint bits = floatBitsToUint(x);
    return uintBitsToFloat(x > 0.0 ? bits + 1u : bits - 1u);
}
float next_float_down(float x) {
    if (x == 0.0) return -uintBitsToFloat(1u);
    const uint bits = floatBitsToUint(x);
    return uintBitsToFloat(x > 0.0 ? bits - 1u : bits + 1u);
}

bool all_finite(vec3 v) {
    return !any(isnan(v)) && !any(isinf(v));
}

struct Ray {
    vec3 origin;
    vec3 direction;
};

// Chapter 02's BvhNode is 32 bytes: min (12), max (12), offset (4), count (4). std430 aligns a vec3 to 16
// bytes, so `vec3 min; vec3 max;` would put max at byte 16 and make the node 48 bytes. The node is read as
// the two vec4 its bytes already are: (min.xyz, max.x) and (max.yz, offset, count), the integers by their
// bits: the C++ array is uploaded as it is.
struct BvhNode {
    vec4 min_max_x;
    vec4 max_yz_offset_count;
};
layout(std430, binding = 0) readonly buffer BvhNodes { BvhNode nodes[]; };

// A primitive (gpu_scene.hpp): info = (kind, material, light, id); p[0..5] by kind (w unused):
//   sphere:   p0 = (centre, radius)
//   quad:     p0 = origin, p1 = u, p2 = v, p3 = unit normal, p4 = a_axis, p5 = b_axis
//   triangle: p0, p1, p2 = the corners
//   plane:    p0 = point, p1 = unit normal, p2 = tangent, p3 = bitangent
const uint kSphere = 0u, kQuad = 1u, kTriangle = 2u, kPlane = 3u;
const uint kNoLight = 0xFFFFFFFFu;
struct Primitive {
    uvec4 info;
    vec4 p[6];
};
layout(std430, binding = 1) readonly buffer Primitives { Primitive primitives[]; };

uniform uint node_count;   // 0: no bounded primitive
uniform uint plane_first;  // planes follow the BVH's primitives
uniform uint plane_count;

// ---- the slab test (chapter 02's aabb.hpp): the entry distance, or ∞ when the ray misses the box ----
float slab_entry(vec3 box_min, vec3 box_max, Ray ray, vec3 inverse_d, float t_max) {
    const float g = gamma_bound(3);
    float t_enter = 0.0;
    float t_exit = t_max;
    for (int i = 0; i < 3; ++i) {
        float t_near, t_far;
        if (abs(inverse_d[i]) < kInfinity) {
            t_near = (box_min[i] - ray.origin[i]) * inverse_d[i];
            t_far = (box_max[i] - ray.origin[i]) * inverse_d[i];
        } else if (ray.direction[i] == 0.0) {
            if (ray.origin[i] < box_min[i] || ray.origin[i] > box_max[i]) return kInfinity;
            continue;
        } else {
            const double d = double(ray.direction[i]);
            t_near = float((double(box_min[i]) - double(ray.origin[i])) / d);
            t_far = float((double(box_max[i]) - double(ray.origin[i])) / d);
        }
        if (t_near > t_far) {
            const float swap = t_near;
            t_near = t_far;
            t_far = swap;
        }
        t_enter = max(t_enter, t_near * (1.0 - 2.0 * g) - uintBitsToFloat(1u));
        t_exit = min(t_exit, t_far * (1.0 + 2.0 * g) + uintBitsToFloat(1u));
    }
    return t_enter <= t_exit ? t_enter : kInfinity;
}

// ---- the sphere (chapter 02's sphere_roots_stable): the nearest root in (0, t_max), or ∞ ----
float intersect_sphere(Ray ray, vec3 center, float r, float t_max) {
    const vec3 f = ray.origin - center;
    const vec3 d = ray.direction;
    const float b = dot(f, d);
    const dvec3 fd = dvec3(f);
    const vec3 perpendicular = vec3(fd - double(b) * dvec3(d));
    const float distance = length(perpendicular);
    const float discriminant = (r - distance) * (r + distance);
    if (discriminant < 0.0) return kInfinity;
    const float c = float(dot(fd, fd) - double(r) * double(r));
    const float sign_b = b < 0.0 || (b == 0.0 && floatBitsToUint(b) != 0u) ? -1.0 : 1.0;  // copysign
    const float q = -(b + sign_b * sqrt(discriminant));
    float t0 = 0.0, t1 = 0.0;
    if (q != 0.0) {
        const float other = c / q;
        t0 = min(q, other);
        t1 = max(q, other);
    }
    if (t0 > 0.0 && t0 < t_max) return t0;
    if (t1 > 0.0 && t1 < t_max) return t1;
    return kInfinity;
}

// ---- the quad (chapter 02's quad.hpp): t, or ∞; (a, b) its coordinates ----
float intersect_quad(Ray ray, Primitive q, float t_max, out vec2 ab) {
    ab = vec2(0.0);
    const vec3 normal = q.p[3].xyz, origin = q.p[0].xyz;
    const float denominator = dot(normal, ray.direction);
    if (denominator == 0.0 || q.p[4].xyz == vec3(0.0)) return kInfinity;
    const float t = dot(normal, origin - ray.origin) / denominator;
    const vec3 offset = (ray.origin + t * ray.direction) - origin;
    const float a = dot(offset, q.p[4].xyz);
    const float b = dot(offset, q.p[5].xyz);
    if (!(t > 0.0 && t < t_max && a >= 0.0 && a <= 1.0 && b >= 0.0 && b <= 1.0)) return kInfinity;
    ab = vec2(a, b);
    return t;
}

// ---- the watertight triangle (Woop, Benthin, Wald 2013; chapter 02's triangle.cpp) ----
struct WatertightRay {
    int kx, ky, kz;
    float sx, sy, sz;
};

WatertightRay make_watertight_ray(Ray ray) {
    const vec3 d = ray.direction;
    const vec3 a = abs(d);
    const int kz = a.x > a.y ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);
    int kx = (kz + 1) % 3;
    int ky = (kx + 1) % 3;
    if (d[kz] < 0.0) {
        const int swap = kx;
        kx = ky;
        ky = swap;
    }
    return WatertightRay(kx, ky, kz, d[kx] / d[kz], d[ky] / d[kz], 1.0 / d[kz]);
}

// Chapter 02's watertight_distance_bound: the bound δt on the rounding of t (PBRT 4 §6.8.7), from the largest
// |x'|, |y'|, |z'| of the three vertices, the largest edge function and |1 / det|. One body for float and
// double: the macro stands in for chapter 02's template.
#define WATERTIGHT_DISTANCE_BOUND(T) \
    T watertight_distance_bound(T max_x, T max_y, T max_z, T max_e, T inverse) { \
        const T delta_z = T(gamma_bound(3)) * max_z; \
        const T delta_x = T(gamma_bound(5)) * (max_x + max_z), delta_y = T(gamma_bound(5)) * (max_y + max_z); \
        const T delta_e = T(2.0) * (T(gamma_bound(2)) * max_x * max_y + delta_y * max_x + delta_x * max_y); \
        return T(3.0) * (T(gamma_bound(3)) * max_e * max_z + delta_e * max_z + delta_z * max_e) * inverse; \
    }
WATERTIGHT_DISTANCE_BOUND(float)
WATERTIGHT_DISTANCE_BOUND(double)

// Below 2^-90, T = U z'_a + V z'_b + W z'_c (a product of three coordinates) may have been rounded among
// float's subnormals, or flushed to zero (GLSL allows it): chapter 02's kSmallestScaledDistance.
const float kSmallestScaledDistance = 8.0779357e-28;

// Chapter 02's watertight_hit_in_double: the products of floats are exact in double, so only the sums and
// the quotient round, and a fused multiply-add changes nothing.
float watertight_hit_in_double(vec3 e, vec3 x, vec3 y, vec3 z, float t_max, out vec2 barycentrics) {
    const float det = e.x + e.y + e.z;
    if (det == 0.0) return kInfinity;
    const double t =
        (double(e.x) * double(z.x) + double(e.y) * double(z.y) + double(e.z) * double(z.z)) / double(det);
    const double max_x = double(max(max(abs(x.x), abs(x.y)), abs(x.z)));
    const double max_y = double(max(max(abs(y.x), abs(y.y)), abs(y.z)));
    const double max_z = double(max(max(abs(z.x), abs(z.y)), abs(z.z)));
    const double max_e = double(max(max(abs(e.x), abs(e.y)), abs(e.z)));
    const double delta_t = watertight_distance_bound(max_x, max_y, max_z, max_e, abs(1.0 / double(det)));
    if (!(t > delta_t && float(t) < t_max)) return kInfinity;
    const float inverse = 1.0 / det;
    barycentrics = vec2(e.y * inverse, e.z * inverse);
    return float(t);
}

float intersect_triangle(Ray ray, WatertightRay s, vec3 p0, vec3 p1, vec3 p2, float t_max,
                         out vec2 barycentrics) {
    barycentrics = vec2(0.0);
    const vec3 a = p0 - ray.origin, b = p1 - ray.origin, c = p2 - ray.origin;
    const float ax = a[s.kx] - s.sx * a[s.kz], ay = a[s.ky] - s.sy * a[s.kz];
    const float bx = b[s.kx] - s.sx * b[s.kz], by = b[s.ky] - s.sy * b[s.kz];
    const float cx = c[s.kx] - s.sx * c[s.kz], cy = c[s.ky] - s.sy * c[s.kz];
    float u = cx * by - cy * bx;
    float v = ax * cy - ay * cx;
    float w = bx * ay - by * ax;
    if (u == 0.0 || v == 0.0 || w == 0.0) {
        u = float(double(cx) * double(by) - double(cy) * double(bx));
        v = float(double(ax) * double(cy) - double(ay) * double(cx));
        w = float(double(bx) * double(ay) - double(by) * double(ax));
    }
    if ((u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0)) return kInfinity;
    const float det = u + v + w;
    if (det == 0.0) return kInfinity;
    const float az = s.sz * a[s.kz], bz = s.sz * b[s.kz], cz = s.sz * c[s.kz];
    const float t_scaled = u * az + v * bz + w * cz;
    if (abs(t_scaled) < kSmallestScaledDistance)
        return watertight_hit_in_double(vec3(u, v, w), vec3(ax, bx, cx), vec3(ay, by, cy), vec3(az, bz, cz), t_max,
                                        barycentrics);
    if (det < 0.0 ? (t_scaled >= 0.0 || t_scaled < t_max * det) : (t_scaled <= 0.0 || t_scaled > t_max * det))
        return kInfinity;
    const float inverse = 1.0 / det;
    const float t = t_scaled * inverse;
    const float max_z = max(max(abs(az), abs(bz)), abs(cz));
    const float max_x = max(max(abs(ax), abs(bx)), abs(cx));
    const float max_y = max(max(abs(ay), abs(by)), abs(cy));
    const float max_e = max(max(abs(u), abs(v)), abs(w));
    const float delta_t = watertight_distance_bound(max_x, max_y, max_z, max_e, abs(inverse));
    if (!(t > delta_t && t < t_max)) return kInfinity;
    barycentrics = vec2(v * inverse, w * inverse);
    return t;
}

// ---- the plane (chapter 02's plane.cpp) ----
float intersect_plane(Ray ray, Primitive plane, float t_max) {
    const float denominator = dot(plane.p[1].xyz, ray.direction);
    if (denominator == 0.0) return kInfinity;
    const float t = dot(plane.p[1].xyz, plane.p[0].xyz - ray.origin) / denominator;
    return t > 0.0 && t < t_max ? t : kInfinity;
}

// The nearest hit found so far, before its hit record is made.
struct Candidate {
    float t;
    uint slot;
    vec2 uv;
};

// Tests primitive `slot`; on a hit nearer than t_max, records it and returns true.
bool test_primitive(Ray ray, WatertightRay sheared, uint slot, float t_max, inout Candidate found) {
    const Primitive p = primitives[slot];
    vec2 uv = vec2(0.0);
    float t = kInfinity;
    if (p.info.x == kSphere) {
        t = intersect_sphere(ray, p.p[0].xyz, p.p[0].w, t_max);
    } else if (p.info.x == kQuad) {
        t = intersect_quad(ray, p, t_max, uv);
    } else if (p.info.x == kTriangle) {
        t = intersect_triangle(ray, sheared, p.p[0].xyz, p.p[1].xyz, p.p[2].xyz, t_max, uv);
    }
    if (t == kInfinity) return false;
    found = Candidate(t, slot, uv);
    return true;
}

// Chapter 02's World::search: the planes, then the BVH (Bvh::traverse), nearest box first. With any_hit,
// returns at the first hit.
bool search(Ray ray, float t_max, bool any_hit, inout Candidate found) {
    bool hit = false;
    for (uint i = plane_first; i < plane_first + plane_count; ++i) {
        const float t = intersect_plane(ray, primitives[i], t_max);
        if (t < kInfinity) {
            found = Candidate(t, i, vec2(0.0));
            t_max = t;
            hit = true;
            if (any_hit) return true;
        }
    }
    if (node_count == 0u) return hit;
    const vec3 inverse_d = vec3(1.0) / ray.direction;
    const WatertightRay sheared = make_watertight_ray(ray);
    if (slab_entry(nodes[0].min_max_x.xyz, vec3(nodes[0].min_max_x.w, nodes[0].max_yz_offset_count.xy), ray,
                   inverse_d, t_max) == kInfinity)
        return hit;
    // EXERCISE(ch11.bvh_traversal) § The scene as GPU memory
    uint stack_node[64];
    float stack_t[64];
    int top = 0;
    uint current = 0u;
    while (true) {
        const BvhNode node = nodes[current];
        const uint offset = floatBitsToUint(node.max_yz_offset_count.z);
        const uint count = floatBitsToUint(node.max_yz_offset_count.w);
        if (count > 0u) {
            for (uint slot = offset; slot < offset + count; ++slot) {
                if (test_primitive(ray, sheared, slot, t_max, found)) {
                    t_max = found.t;
                    hit = true;
                    if (any_hit) return true;
                }
            }
        } else {
            const uint first = current + 1u, second = offset;
            const BvhNode a = nodes[first], b = nodes[second];
            const float t_first = slab_entry(a.min_max_x.xyz, vec3(a.min_max_x.w, a.max_yz_offset_count.xy),
                                             ray, inverse_d, t_max);
            const float t_second = slab_entry(b.min_max_x.xyz, vec3(b.min_max_x.w, b.max_yz_offset_count.xy),
                                              ray, inverse_d, t_max);
            if (t_first < kInfinity && t_second < kInfinity) {
                const bool first_nearer = t_first <= t_second;
                stack_node[top] = first_nearer ? second : first;
                stack_t[top] = first_nearer ? t_second : t_first;
                ++top;
                current = first_nearer ? first : second;
                continue;
            }
            if (t_first < kInfinity) {
                current = first;
                continue;
            }
            if (t_second < kInfinity) {
                current = second;
                continue;
            }
        }
        // Pop the next subtree that may still hold a nearer hit.
        do {
            if (top == 0) return hit;
            --top;
        } while (stack_t[top] > t_max);
        current = stack_node[top];
    }
    return hit;
    // END EXERCISE
}

// ---- the hit record (chapter 02's hit.hpp and World::make_hit) ----
struct Hit {
    float t;
    vec3 point;
    vec3 point_error;
    vec3 normal;  // unit, facing the ray
    bool front_face;
    uint material;
    uint light;  // the light picker's index of this emitter, kNoLight for none
    uint id;     // the primitive's number in scene order
};

void set_face_normal(inout Hit hit, vec3 direction, vec3 outward) {
    hit.front_face = dot(direction, outward) < 0.0;
    hit.normal = hit.front_face ? outward : -outward;
}

Hit make_hit(Ray ray, Candidate found) {
    const Primitive p = primitives[found.slot];
    Hit hit;
    hit.t = found.t;
    hit.material = p.info.y;
    hit.light = p.info.z;
    hit.id = p.info.w;
    const vec3 at_t = ray.origin + found.t * ray.direction;
    if (p.info.x == kPlane) {
        const vec3 offset = at_t - p.p[0].xyz;
        const vec3 along_t = dot(offset, p.p[2].xyz) * p.p[2].xyz;
        const vec3 along_b = dot(offset, p.p[3].xyz) * p.p[3].xyz;
        hit.point = p.p[0].xyz + along_t + along_b;
        hit.point_error = gamma_bound(5) * (abs(p.p[0].xyz) + abs(along_t) + abs(along_b));
        set_face_normal(hit, ray.direction, p.p[1].xyz);
    } else if (p.info.x == kSphere) {
        const vec3 c = p.p[0].xyz;
        const float r = p.p[0].w;
        vec3 n = (at_t - c) / r;
        const float n_length = length(n);
        n = n_length > 0.0 ? n / n_length : vec3(0.0, 1.0, 0.0);
        const vec3 radial = r * n;
        hit.point = c + radial;
        hit.point_error = gamma_bound(5) * (abs(c) + abs(radial));
        set_face_normal(hit, ray.direction, n);
    } else if (p.info.x == kQuad) {
        const vec3 along_u = found.uv.x * p.p[1].xyz, along_v = found.uv.y * p.p[2].xyz;
        hit.point = p.p[0].xyz + along_u + along_v;
        hit.point_error = gamma_bound(3) * (abs(p.p[0].xyz) + abs(along_u) + abs(along_v));
        set_face_normal(hit, ray.direction, p.p[3].xyz);
    } else {
        const float b1 = found.uv.x, b2 = found.uv.y;
        const vec3 w0 = (1.0 - b1 - b2) * p.p[0].xyz, w1 = b1 * p.p[1].xyz, w2 = b2 * p.p[2].xyz;
        hit.point = w0 + w1 + w2;
        hit.point_error = gamma_bound(7) * (abs(w0) + abs(w1) + abs(w2));
        const vec3 n = cross(p.p[1].xyz - p.p[0].xyz, p.p[2].xyz - p.p[0].xyz);
        const float n_length = length(n);
        set_face_normal(hit, ray.direction, n_length > 0.0 ? n / n_length : vec3(0.0, 0.0, 1.0));
    }
    return hit;
}

// The nearest hit with 0 < t < t_max (World::intersect).
bool intersect_scene(Ray ray, float t_max, out Hit hit) {
    Candidate found = Candidate(kInfinity, 0u, vec2(0.0));
    if (!search(ray, t_max, false, found)) return false;
    hit = make_hit(ray, found);
    return true;
}

// Whether anything is hit with 0 < t < t_max (World::occluded).
bool occluded(Ray ray, float t_max) {
    Candidate found = Candidate(kInfinity, 0u, vec2(0.0));
    return search(ray, t_max, true, found);
}

// ---- chapter 03's robust ray offset and shadow segment ----
vec3 offset_origin(Hit hit, vec3 direction) {
    const float delta = dot(abs(hit.normal), hit.point_error);
    vec3 offset = delta * hit.normal;
    if (dot(direction, hit.normal) < 0.0) offset = -offset;
    vec3 origin = hit.point + offset;
    for (int i = 0; i < 3; ++i) {
        if (offset[i] > 0.0) origin[i] = next_float_up(origin[i]);
        if (offset[i] < 0.0) origin[i] = next_float_down(origin[i]);
    }
    return origin;
}

Ray spawn_ray(Hit hit, vec3 direction) {
    return Ray(offset_origin(hit, direction), direction);
}

// The segment from `hit` to `target`, stopping short of it (chapter 03's spawn_shadow_ray); t_max out.
Ray spawn_shadow_ray(Hit hit, vec3 target, out float t_max) {
    const vec3 origin = offset_origin(hit, target - hit.point);
    const vec3 to_target = target - origin;
    const float distance = length(to_target);
    if (!(distance > 0.0)) {
        t_max = 0.0;
        return Ray(origin, hit.normal);
    }
    const vec3 direction = to_target / distance;
    const float rounding = gamma_bound(8) * dot(abs(direction), abs(target) + abs(origin));
    t_max = max(0.0, (1.0 - 1e-4) * distance - rounding);
    return Ray(origin, direction);
}
