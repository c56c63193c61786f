// The path tracer as a compute shader: one invocation per pixel of the band this dispatch covers, 8×8 pixels
// a work group. Each invocation takes the pass's samples of its pixel in order, sums them, and adds the sum
// into the accumulation image (rgba32f: the radiance sums and the sample count).

layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f, binding = 0) uniform image2D accumulation;

uniform int band_first_row;  // the rows [band_first_row, band_first_row + band_rows) of the image
uniform int band_rows;
uniform int first_sample;  // the pass: samples [first_sample, first_sample + pass_samples)
uniform int pass_samples;

void main() {
    const ivec2 pixel = ivec2(gl_GlobalInvocationID.x, band_first_row + int(gl_GlobalInvocationID.y));
    if (pixel.x >= image_size.x || pixel.y >= band_first_row + band_rows) return;
    vec3 sum = vec3(0.0);
    for (int s = first_sample; s < first_sample + pass_samples; ++s) sum += render_sample(pixel, s);
    // OpenGL's images start at the bottom row: pixel row y is texel row H − 1 − y.
    const ivec2 texel = ivec2(pixel.x, image_size.y - 1 - pixel.y);
    imageStore(accumulation, texel, imageLoad(accumulation, texel) + vec4(sum, float(pass_samples)));
    flush_ray_counts();
}
