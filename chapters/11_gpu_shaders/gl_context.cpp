#include "gl_context.hpp"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <vector>

#include "gl_api.hpp"
#include "rt/core/errors.hpp"

namespace rt {
namespace {

constexpr const char* kInstall =
    "install Mesa's EGL and OpenGL drivers (SUDO=$(command -v sudo); $SUDO apt-get install libegl-mesa0 "
    "libgl1-mesa-dri) or a GPU vendor's driver";

bool has_extension(const char* list, std::string_view name) {
    if (!list) return false;
    const std::string_view all(list);
    for (std::size_t at = all.find(name); at != std::string_view::npos; at = all.find(name, at + 1)) {
        const bool starts = at == 0 || all[at - 1] == ' ';
        const bool ends = at + name.size() == all.size() || all[at + name.size()] == ' ';
        if (starts && ends) return true;
    }
    return false;
}

// An initialised display on `platform`, or EGL_NO_DISPLAY; `why` says what failed.
EGLDisplay open_display(EglPlatform platform, std::string& why, std::string& used) {
    const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    const auto get_platform_display =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!get_platform_display) {
        why = "EGL has no eglGetPlatformDisplayEXT (EGL_EXT_platform_base)";
        return EGL_NO_DISPLAY;
    }
    EGLint major = 0, minor = 0;
    if (platform != EglPlatform::kDevice) {
        if (has_extension(client, "EGL_MESA_platform_surfaceless")) {
            EGLDisplay d = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
            if (d != EGL_NO_DISPLAY && eglInitialize(d, &major, &minor)) {
                used = "EGL surfaceless";
                return d;
            }
            why = "the EGL surfaceless platform did not initialise";
        } else {
            why = "EGL has no surfaceless platform (EGL_MESA_platform_surfaceless)";
        }
        if (platform == EglPlatform::kSurfaceless) return EGL_NO_DISPLAY;
    }
    const auto query_devices =
        reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    if (!has_extension(client, "EGL_EXT_platform_device") || !query_devices) {
        why += std::string(why.empty() ? "" : "; ") + "EGL has no device platform (EGL_EXT_platform_device)";
        return EGL_NO_DISPLAY;
    }
    EGLint count = 0;
    if (!query_devices(0, nullptr, &count) || count == 0) {
        why += std::string(why.empty() ? "" : "; ") + "EGL lists no device";
        return EGL_NO_DISPLAY;
    }
    std::vector<EGLDeviceEXT> devices(std::size_t(count), nullptr);
    query_devices(count, devices.data(), &count);
    for (EGLint i = 0; i < count; ++i) {
        EGLDisplay d = get_platform_display(EGL_PLATFORM_DEVICE_EXT, devices[std::size_t(i)], nullptr);
        if (d != EGL_NO_DISPLAY && eglInitialize(d, &major, &minor)) {
            used = "EGL device " + std::to_string(i);
            return d;
        }
    }
    why += std::string(why.empty() ? "" : "; ") + "no EGL device initialised";
    return EGL_NO_DISPLAY;
}

}  // namespace

GlContext::GlContext(EglPlatform platform) {
    std::string why, used;
    EGLDisplay display = open_display(platform, why, used);
    if (display == EGL_NO_DISPLAY) throw GlUnavailable("no OpenGL: " + why + "; " + kInstall);
    display_ = display;
    if (!eglBindAPI(EGL_OPENGL_API)) {
        eglTerminate(display);
        throw GlUnavailable("no OpenGL: EGL does not offer desktop OpenGL; " + std::string(kInstall));
    }
    // OpenGL 4.5 core: compute shaders, shader storage buffers, image load/store, direct state access.
    const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                 4,
                                 EGL_CONTEXT_MINOR_VERSION,
                                 5,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                 EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                 EGL_NONE};
    EGLContext context = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
    if (context == EGL_NO_CONTEXT || !eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
        if (context != EGL_NO_CONTEXT) eglDestroyContext(display, context);
        eglTerminate(display);
        throw GlUnavailable("no OpenGL 4.5 core context on " + used +
                            " (it needs EGL_KHR_no_config_context and EGL_KHR_surfaceless_context); " +
                            kInstall);
    }
    context_ = context;
    const auto text = [](GLenum name) {
        const auto* s = reinterpret_cast<const char*>(glGetString(name));
        return std::string(s ? s : "?");
    };
    const std::string renderer = text(GL_RENDERER);
    software_ =
        renderer.find("llvmpipe") != std::string::npos || renderer.find("softpipe") != std::string::npos;
    description_ = renderer + ", OpenGL " + text(GL_VERSION) + ", " + used;
}

// The display stays initialised until the process ends (EGL returns the same one to the next context):
// eglTerminate would unload the driver (Mesa's swrast_dri.so), and LeakSanitizer would then report what the
// driver keeps for the life of the process as lost, in a library it can no longer name. Left loaded, the
// driver's memory stays reachable, and the sanitizer build checks the course's own allocations with no
// suppression.
GlContext::~GlContext() {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
    eglReleaseThread();
}

}  // namespace rt
