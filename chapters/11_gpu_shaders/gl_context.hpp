// A headless OpenGL 4.5 core context through EGL: no window, no display server. EGL's surfaceless platform
// (EGL_MESA_platform_surfaceless) first, then its device platform (EGL_EXT_platform_device: the first
// device, a GPU or Mesa's software one). eglGetDisplay(EGL_DEFAULT_DISPLAY) is not used: without a display
// server it fails. With Mesa and no GPU the context is llvmpipe, which compiles shaders to the CPU's SIMD
// units (8 floats a lane group with AVX2) and runs them on LP_NUM_THREADS threads.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

#include "rt/core/enum_names.hpp"

namespace rt {

// No usable OpenGL: what is missing, and how to install it.
class GlUnavailable : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// kAuto: surfaceless, then device.
enum class EglPlatform { kAuto, kSurfaceless, kDevice };

constexpr auto names_of(EglPlatform) {
    return enum_names<EglPlatform>("--egl", {{EglPlatform::kAuto, "auto"},
                                             {EglPlatform::kSurfaceless, "surfaceless"},
                                             {EglPlatform::kDevice, "device"}});
}

class GlContext {
  public:
    // Makes the context current on this thread. Throws GlUnavailable.
    explicit GlContext(EglPlatform platform = EglPlatform::kAuto);
    ~GlContext();
    GlContext(const GlContext&) = delete;
    GlContext& operator=(const GlContext&) = delete;

    // GL_RENDERER, GL_VERSION and the EGL platform: "llvmpipe (LLVM 15.0.6, 256 bits), OpenGL 4.5 (Core
    // Profile) Mesa 22.3.6, EGL surfaceless".
    const std::string& description() const { return description_; }
    // Whether the renderer is Mesa's software rasteriser (llvmpipe, softpipe).
    bool software() const { return software_; }

  private:
    void* display_ = nullptr;
    void* context_ = nullptr;
    std::string description_;
    bool software_ = false;
};

}  // namespace rt
