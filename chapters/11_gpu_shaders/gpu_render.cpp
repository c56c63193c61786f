#include "gpu_render.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include "04_direct_lighting/light_set.hpp"
#include "04_direct_lighting/material_table.hpp"
#include "05_recursive_gi/termination.hpp"
#include "07_bsdf_refraction/refraction_materials.hpp"
#include "embedded_shaders.hpp"
#include "gl_program.hpp"
#include "rt/core/errors.hpp"
#include "rt/render/interrupt.hpp"
#include "rt/render/parallel_for.hpp"
#include "rt/render/progress.hpp"

namespace rt {
namespace {

using Clock = std::chrono::steady_clock;

// A dispatch is kept between these durations by halving or doubling its rows.
constexpr double kShortestDispatch = 0.010;
constexpr double kLongestDispatch = 0.100;
// The first band: this many pixels (at least one row).
constexpr int kFirstBandPixels = 4096;

std::vector<ShaderStage> stages_of(ShaderKind kind) {
    if (kind == ShaderKind::kCompute) return {{GL_COMPUTE_SHADER, "trace.comp", shaders::k_trace_comp}};
    return {{GL_VERTEX_SHADER, "fullscreen.vert", shaders::k_fullscreen_vert},
            {GL_FRAGMENT_SHADER, "trace.frag", shaders::k_trace_frag}};
}

// An rgba32f texture of the image's size, zeroed.
GLuint make_accumulation(int width, int height) {
    GLuint texture = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &texture);
    glTextureStorage2D(texture, 1, GL_RGBA32F, width, height);
    const float zero[4] = {0, 0, 0, 0};
    glClearTexImage(texture, 0, GL_RGBA, GL_FLOAT, zero);
    return texture;
}

GLint gl_integer(GLenum name, GLuint index = 0) {
    GLint value = 0;
    glGetIntegeri_v(name, index, &value);
    return value;
}

// The camera, the image's size, its samples and its seed, as the shader's uniforms.
void set_frame_uniforms(const GlProgram& p, const PinholeCamera& camera, const RenderSettings& settings) {
    const int spp = settings.samples_per_pixel;
    p.set("camera_eye", float(camera.eye.x), float(camera.eye.y), float(camera.eye.z));
    p.set("camera_forward", float(camera.forward.x), float(camera.forward.y), float(camera.forward.z));
    p.set("camera_right", float(camera.right.x), float(camera.right.y), float(camera.right.z));
    p.set("camera_up", float(camera.up.x), float(camera.up.y), float(camera.up.z));
    p.set("camera_half_size", float(camera.half_width), float(camera.half_height));
    p.set("camera_lens_radius", float(camera.lens_radius));
    p.set("camera_focus_distance", float(camera.focus_distance));
    p.set("image_size", settings.width, settings.height);
    p.set("spp", spp);
    p.set("strata", int(std::sqrt(double(spp))));
    p.set("seed_bits", std::uint32_t(settings.seed), std::uint32_t(settings.seed >> 32u));
}

// One band of rows [y0, y0 + rows) of a pass's samples [first, first + count), waited for.
void draw_band(const GlProgram& p, ShaderKind kind, int width, int height, int y0, int rows, int first,
               int count) {
    p.set("first_sample", first);
    p.set("pass_samples", count);
    if (kind == ShaderKind::kCompute) {
        p.set("band_first_row", y0);
        p.set("band_rows", rows);
        glDispatchCompute(GLuint((width + 7) / 8), GLuint((rows + 7) / 8), 1);
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    } else {
        glScissor(0, height - (y0 + rows), width, rows);  // the texel rows of pixel rows y0 …
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    }
    glFinish();
}

// The image of accumulation texture `total`, read back a texel row at a time (a whole large image is more
// bytes than one call may name): texel row r is pixel row H − 1 − r; each pixel is its sums over its count.
Image read_accumulation(GLuint total, int width, int height) {
    Image image(width, height);
    std::vector<float> row(std::size_t(width) * 4);
    for (int y = 0; y < height; ++y) {
        glGetTextureSubImage(total, 0, 0, height - 1 - y, 0, width, 1, 1, GL_RGBA, GL_FLOAT,
                             GLsizei(row.size() * sizeof(float)), row.data());
        for (int x = 0; x < width; ++x) {
            const float* t = &row[std::size_t(x) * 4];
            image.at(x, y) = t[3] > 0 ? Color(t[0], t[1], t[2]) / Real(t[3]) : Color(0);
        }
    }
    return image;
}

// The fragment shader's framebuffer on the accumulation texture, and the vertex array its draws need (none
// for the compute shader).
struct FragmentTarget {
    GLuint framebuffer = 0, vertex_array = 0;
};

// Where the passes add their samples: texture `total`, bound as an image for the compute shader, or as the
// colour of a framebuffer that adds what each draw writes for the fragment shader.
FragmentTarget bind_accumulation(ShaderKind kind, GLuint total, int width, int height) {
    FragmentTarget target;
    if (kind == ShaderKind::kCompute) {
        glBindImageTexture(0, total, 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
        return target;
    }
    glCreateFramebuffers(1, &target.framebuffer);
    glNamedFramebufferTexture(target.framebuffer, GL_COLOR_ATTACHMENT0, total, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
    glCreateVertexArrays(1, &target.vertex_array);  // core profile draws need one, even with no attributes
    glBindVertexArray(target.vertex_array);
    glViewport(0, 0, width, height);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    glEnable(GL_SCISSOR_TEST);
    return target;
}

void unbind_accumulation(FragmentTarget& target) {
    if (!target.framebuffer) return;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &target.framebuffer);
    glDeleteVertexArrays(1, &target.vertex_array);
    glDisable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);
}

// The rows of the next band: a band that took `seconds` is doubled below kShortestDispatch, halved above
// kLongestDispatch.
int next_band_rows(int rows, double seconds, int height) {
    if (seconds < kShortestDispatch) rows = std::min(2 * rows, height);
    if (seconds > kLongestDispatch) rows = std::max(1, rows / 2);
    return rows;
}

// Adds the rays the shader counted into `rays`, and zeroes its counters.
void take_ray_counts(const GlBuffer& counters, RayCounts& rays) {
    std::array<std::uint32_t, 5> counts{};
    counters.read(counts.data(), sizeof counts);
    counters.zero();
    for (std::size_t k = 0; k < counts.size(); ++k) rays.add(RayKind(k), counts[k]);
}

}  // namespace

void check_image_size(int width, int height, ShaderKind kind) {
    // The largest side each part of the render takes: the accumulation texture, and the compute shader's
    // workgroups of 8×8 pixels, or the fragment shader's framebuffer and viewport.
    struct Limit {
        const char* name;
        long long side;
    };
    std::vector<Limit> limits;
    GLint texture = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &texture);
    limits.push_back({"GL_MAX_TEXTURE_SIZE", texture});
    if (kind == ShaderKind::kCompute) {
        const long long groups = std::min(gl_integer(GL_MAX_COMPUTE_WORK_GROUP_COUNT, 0),
                                          gl_integer(GL_MAX_COMPUTE_WORK_GROUP_COUNT, 1));
        limits.push_back({"GL_MAX_COMPUTE_WORK_GROUP_COUNT, 8 pixels a group", 8 * groups});
    } else {
        GLint framebuffer_width = 0, framebuffer_height = 0, viewport[2] = {0, 0};
        glGetIntegerv(GL_MAX_FRAMEBUFFER_WIDTH, &framebuffer_width);
        glGetIntegerv(GL_MAX_FRAMEBUFFER_HEIGHT, &framebuffer_height);
        glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
        limits.push_back(
            {"GL_MAX_FRAMEBUFFER_WIDTH and _HEIGHT", std::min(framebuffer_width, framebuffer_height)});
        limits.push_back({"GL_MAX_VIEWPORT_DIMS", std::min(viewport[0], viewport[1])});
    }
    const Limit smallest = *std::min_element(limits.begin(), limits.end(),
                                             [](const Limit& a, const Limit& b) { return a.side < b.side; });
    if (std::max(width, height) > smallest.side) {
        throw InputError("image " + std::to_string(width) + "x" + std::to_string(height) +
                         ": this OpenGL's " + std::string(to_string(kind)) + " shader renders at most " +
                         std::to_string(smallest.side) + " pixels a side (" + smallest.name +
                         "): give --width and --height of at most " + std::to_string(smallest.side));
    }
}

struct GpuRenderer::State {
    State(const Scene& scene_, const GpuScene& gpu, ShaderKind kind_)
        : scene(scene_),
          kind(kind_),
          program(stages_of(kind_)),
          nodes(gpu.nodes),
          primitives(gpu.primitives),
          materials(gpu.materials),
          lights(gpu.lights),
          counters(nullptr, 5 * sizeof(std::uint32_t)) {}

    // The buffers at the shader's binding points, the ray counters zeroed, the program in use.
    void bind() const {
        nodes.bind(0);
        primitives.bind(1);
        materials.bind(2);
        lights.bind(3);
        counters.bind(4);
        counters.zero();
        program.use();
    }

    const Scene& scene;
    ShaderKind kind;
    GlProgram program;
    GlBuffer nodes, primitives, materials, lights, counters;
};

GpuRenderer::GpuRenderer(const GlContext& context, const Scene& scene, const EffectSet& simulated,
                         ShaderKind kind) {
    // What chapter 07's renderer builds, but its World: the GPU traces its own copy of the shapes.
    const MaterialTable materials(scene, simulated, refraction_materials());
    const LightSet lights = collect_lights(scene);
    const LightPicker picker(lights);
    const GpuScene gpu = flatten_scene(scene, materials, lights, picker);
    state_ = std::make_unique<State>(scene, gpu, kind);
    const GlProgram& p = state_->program;
    p.set("node_count", std::uint32_t(gpu.nodes.size()));
    p.set("plane_first", gpu.plane_first);
    p.set("plane_count", gpu.plane_count);
    p.set("light_count", std::uint32_t(gpu.lights.size()));
    p.set("light_total", gpu.light_total);
    p.set("has_environment", gpu.environment.has_value());
    const Color env = gpu.environment.value_or(Color(0));
    p.set("environment_radiance", float(env.r), float(env.g), float(env.b));
    p.set("simulate_direct", simulated.contains(Effect::kDirect));
    p.set("simulate_indirect", simulated.contains(Effect::kIndirect));
    p.set("simulate_shadows", simulated.contains(Effect::kShadows));
    p.set("max_depth", scene.max_depth.value_or(kSafetyDepthCap));
    notes_.push_back("renderer: chapter 06's path loop with MIS as a " + std::string(to_string(kind)) +
                     " shader on " + context.description());
    notes_.push_back("GPU buffers: " + std::to_string(gpu.nodes.size()) + " BVH nodes, " +
                     std::to_string(gpu.primitives.size()) + " primitives, " +
                     std::to_string(gpu.materials.size()) + " materials, " +
                     std::to_string(gpu.lights.size()) + " lights (" + std::to_string(gpu_bytes(gpu)) +
                     " bytes)");
    for (const std::string& note : materials.notes()) notes_.push_back(note);
    for (const std::string& note : gpu.notes) notes_.push_back(note);
}

GpuRenderer::~GpuRenderer() = default;

void GpuRenderer::share_random_streams(bool shared) const {
    state_->program.set("shared_streams", shared);
}

RenderResult GpuRenderer::render(const RenderSettings& settings) const {
    const State& s = *state_;
    const GlProgram& p = s.program;
    const int width = settings.width, height = settings.height, spp = settings.samples_per_pixel;
    check_image_size(width, height, s.kind);
    set_frame_uniforms(p, make_pinhole_camera(s.scene.camera, width, height), settings);
    s.bind();

    const GLuint total = make_accumulation(width, height);
    const GLuint backup = make_accumulation(width, height);
    FragmentTarget target = bind_accumulation(s.kind, total, width, height);
    // The driver compiles the shader to machine code at its first use (llvmpipe: about 2 s): a band of no
    // samples does it before the clock starts.
    draw_band(p, s.kind, width, height, 0, 1, 0, 0);

    RenderResult result;
    Progress progress(settings.progress);
    const auto start = Clock::now();
    const double total_samples = double(width) * double(height) * double(spp);
    std::uint64_t samples_kept = 0;
    int samples_per_pixel = 0;
    int rows = std::clamp(kFirstBandPixels / width, 1, height);
    const int per_pass = pass_samples(spp);
    for (int first = 0, end = 1; first < spp && !interrupt_requested();
         first = end, end = std::min(spp, end + per_pass)) {
        glCopyImageSubData(total, GL_TEXTURE_2D, 0, 0, 0, 0, backup, GL_TEXTURE_2D, 0, 0, 0, 0, width, height,
                           1);
        // The pass's rows are the engine's items, all on this thread (the OpenGL context is this thread's): a
        // row not yet drawn starts a band there, and the band's other rows are then handed on at no cost.
        int drawn = 0;  // rows [0, drawn) have the pass's samples
        std::uint64_t pass_taken = 0;
        parallel_for(
            std::size_t(height), {.threads = 1, .stop = interrupt_requested}, [&](std::size_t row, int) {
                if (int(row) < drawn) return;
                const int band = std::min(rows, height - drawn);
                const auto band_start = Clock::now();
                draw_band(p, s.kind, width, height, drawn, band, first, end - first);
                rows = next_band_rows(rows, std::chrono::duration<double>(Clock::now() - band_start).count(),
                                      height);
                take_ray_counts(s.counters, result.rays);
                drawn += band;
                pass_taken += std::uint64_t(band) * std::uint64_t(width) * std::uint64_t(end - first);
                progress.show(double(samples_kept + pass_taken) / total_samples,
                              std::chrono::duration<double>(Clock::now() - start).count());
            });
        if (drawn < height) {  // an interrupt stopped the pass: it is dropped
            glCopyImageSubData(backup, GL_TEXTURE_2D, 0, 0, 0, 0, total, GL_TEXTURE_2D, 0, 0, 0, 0, width,
                               height, 1);
            break;
        }
        samples_kept += pass_taken;
        samples_per_pixel = end;
        if (settings.observer && !interrupt_requested()) {
            const Image image = read_accumulation(total, width, height);
            settings.observer->after_pass(
                PassReport{image, std::uint32_t(end), samples_kept, result.rays, samples_kept,
                           std::chrono::duration<double>(Clock::now() - start).count()});
        }
    }
    progress.clear();

    result.image = read_accumulation(total, width, height);
    unbind_accumulation(target);
    glDeleteTextures(1, &total);
    glDeleteTextures(1, &backup);
    result.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    result.samples = samples_kept;
    result.samples_per_pixel = samples_per_pixel;
    result.interrupted = samples_per_pixel < spp;
    if (samples_per_pixel == 0) {
        result.unsampled_pixels = std::uint64_t(width) * std::uint64_t(height);
        result.unsampled_region = {0, 0, width, height};
    }
    return result;
}

}  // namespace rt
