// What the tests ask the shader's own functions (tests/11_gpu_shaders_test.cpp), one entry per invocation:
//   mode 0: the random numbers of (pixel, sample) under the seed: in = (pixel lo, pixel hi, sample lo,
//           sample hi); out[2i] = the first four next_uint, out[2i + 1] = the bits of four next_real after them.
//   mode 1: the nearest hit of a ray: in[2i] = origin bits and t_max, in[2i + 1] = direction bits;
//           out[2i] = (hit, t bits, primitive id, front face), out[2i + 1] = (normal bits, light).

layout(local_size_x = 64) in;
layout(std430, binding = 5) readonly buffer ProbeInput { uvec4 probe_in[]; };
layout(std430, binding = 6) writeonly buffer ProbeOutput { uvec4 probe_out[]; };

uniform int probe_mode;
uniform uint probe_count;

void main() {
    const uint i = gl_GlobalInvocationID.x;
    if (i >= probe_count) return;
    if (probe_mode == 0) {
        const uvec4 q = probe_in[i];
        Pcg32 rng = pcg_for_sample(packUint2x32(q.xy), packUint2x32(q.zw), packUint2x32(seed_bits));
        uvec4 words;
        for (int k = 0; k < 4; ++k) words[k] = pcg_next_uint(rng);
        uvec4 reals;
        for (int k = 0; k < 4; ++k) reals[k] = floatBitsToUint(pcg_next_real(rng));
        probe_out[2u * i] = words;
        probe_out[2u * i + 1u] = reals;
    } else {
        const uvec4 o = probe_in[2u * i], d = probe_in[2u * i + 1u];
        const Ray ray = Ray(uintBitsToFloat(o.xyz), uintBitsToFloat(d.xyz));
        Hit hit;
        if (intersect_scene(ray, uintBitsToFloat(o.w), hit)) {
            probe_out[2u * i] = uvec4(1u, floatBitsToUint(hit.t), hit.id, hit.front_face ? 1u : 0u);
            probe_out[2u * i + 1u] = uvec4(floatBitsToUint(hit.normal), hit.light);
        } else {
            probe_out[2u * i] = uvec4(0u);
            probe_out[2u * i + 1u] = uvec4(0u);
        }
    }
}
