// Chapter 11: the path tracer as a shader. Chapter 06's path loop with chapter 07's glass, run by OpenGL as a
// compute shader (`--shader compute`, the default) or as a fragment shader over a full-screen triangle
// (`--shader fragment`), on whatever EGL offers without a display: a GPU's driver, or Mesa's llvmpipe on the
// CPU. Without a usable OpenGL it says what is missing and how to install it, and exits 2.
#include "gl_context.hpp"
#include "gpu_render.hpp"
#include "rt/core/errors.hpp"
#include "rt/flags/enum_flag.hpp"
#include "rt/run/app.hpp"

int main(int argc, char** argv) {
    using namespace rt;
    ShaderKind shader = ShaderKind::kCompute;
    EglPlatform egl = EglPlatform::kAuto;
    const ChapterInfo chapter{
        "ch11_gpu_shaders",
        "Chapter 11: the path tracer as a GLSL shader (compute or fragment), headless "
        "OpenGL 4.5 through EGL, on a GPU or on Mesa's llvmpipe",
        "ch07_default.json",
        kGpuChapterEffects,
        {},
        [] {
            return "the GPU sums each pixel's samples in float, not in the exact sums a piece of "
                   "a render needs: it renders whole (no --samples, --resume or mpirun with "
                   "several ranks)";
        }};
    auto flags = [&](CLI::App& app) {
        add_enum_option(app, shader, "Which shader traces the paths: " + joined_names<ShaderKind>());
        add_enum_option(app, egl,
                        "EGL platform: auto (surfaceless, then device), surfaceless, or device (a GPU's "
                        "driver where Mesa would take the surfaceless one)");
    };
    auto render = [&](const RunContext& context) -> std::optional<ChapterRun> {
        try {
            const GlContext gl(egl);
            const GpuRenderer renderer(gl, context.scene, context.simulated, shader);
            ChapterRun run{renderer.render(context.settings), renderer.notes(), std::nullopt};
            run.notes.push_back("--threads does not apply: the GPU (llvmpipe: LP_NUM_THREADS) decides");
            return run;
        } catch (const GlUnavailable& e) {
            throw InputError(e.what());
        }
    };
    return run_chapter(argc, argv, chapter, flags, render);
}
