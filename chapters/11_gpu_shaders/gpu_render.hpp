// Rendering on the GPU: the flattened scene uploaded once, then the path tracer run as a compute shader or
// as a fragment shader over a full-screen triangle, in passes like the CPU's render loop (one sample per
// pixel, then ⌈spp/8⌉ up to 16 a pass). A pass is cut into bands of rows, one dispatch (or draw) each, their
// height adapted so that a dispatch takes 10 to 100 ms: the driver's watchdog never sees a long one, Ctrl-C
// is looked for after each, and the progress bar moves. A pass cut short by Ctrl-C is dropped, so every pixel
// keeps whole passes, as on the CPU. Each pixel's samples are summed in order by the one invocation that owns
// it, so the image does not depend on how the GPU schedules its threads (llvmpipe's LP_NUM_THREADS).
#pragma once

#include <memory>
#include <string_view>

#include "01_ray_generation/camera.hpp"
#include "gl_context.hpp"
#include "gpu_scene.hpp"
#include "rt/core/effect_set.hpp"
#include "rt/core/scene.hpp"
#include "rt/render/render_loop.hpp"

namespace rt {

// What chapter 11 simulates: chapter 07's effects but shading normals (the shader shades meshes faceted).
inline constexpr EffectSet kGpuChapterEffects =
    EffectSet::all().without({Effect::kMedia, Effect::kShadingNormals});

enum class ShaderKind { kCompute, kFragment };

constexpr auto names_of(ShaderKind) {
    return enum_names<ShaderKind>("--shader", {{ShaderKind::kCompute, "compute"}, {ShaderKind::kFragment, "fragment"}});
}

// Throws InputError, naming the limit, when this OpenGL (its context current on this thread) cannot hold an
// image of width × height for the `kind` shader: beyond its limits a texture or a dispatch silently fails and
// the image reads black.
void check_image_size(int width, int height, ShaderKind kind);

class GpuRenderer {
  public:
    // Flattens and uploads the scene and compiles the shader, on `context` (current on this thread); the
    // context and the scene must outlive the renderer. The effects are chapter 06's: direct, indirect and
    // shadows switch parts of the path loop; the material table holds the rest.
    GpuRenderer(const GlContext& context, const Scene& scene, const EffectSet& simulated, ShaderKind kind);
    ~GpuRenderer();
    GpuRenderer(const GpuRenderer&) = delete;
    GpuRenderer& operator=(const GpuRenderer&) = delete;

    // The whole render of settings.samples_per_pixel samples (no sample range, no resume). The result has
    // no exact sums (the GPU sums in float): a run cannot be split or resumed.
    RenderResult render(const RenderSettings& settings) const;

    // The lesson's divergence experiment: every pixel takes pixel 0's random numbers, so neighbouring paths
    // stay alike (a blotchy image, for timing only). Off by default.
    void share_random_streams(bool shared) const;

    // The notes for the run's summary: the shader, the device, the buffers, the material stand-ins.
    const std::vector<std::string>& notes() const { return notes_; }

  private:
    struct State;
    std::unique_ptr<State> state_;
    std::vector<std::string> notes_;
};

}  // namespace rt
