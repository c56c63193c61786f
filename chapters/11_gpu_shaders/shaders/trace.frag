// The path tracer as a fragment shader, as the source text describes: a full-screen triangle covers every
// pixel, and each fragment computes its pixel's colour independently. The pass's samples of the pixel are
// summed here; additive blending (GL_ONE, GL_ONE) adds the sum into the rgba32f accumulation target. The
// scissor rectangle limits a draw to a band of rows, as the compute shader's dispatch is.

uniform int first_sample;
uniform int pass_samples;

layout(location = 0) out vec4 sum_out;

void main() {
    // gl_FragCoord is the texel's centre, from the bottom row: pixel row y is texel row H − 1 − y.
    const ivec2 texel = ivec2(gl_FragCoord.xy);
    const ivec2 pixel = ivec2(texel.x, image_size.y - 1 - texel.y);
    vec3 sum = vec3(0.0);
    for (int s = first_sample; s < first_sample + pass_samples; ++s) sum += render_sample(pixel, s);
    sum_out = vec4(sum, float(pass_samples));
    flush_ray_counts();
}
