#include "render/HeadlessGlContext.h"

// EGL's own header, not epoxy's: this file makes no GL calls, and epoxy resolves GL functions through
// whichever context (GLX or EGL) is current once this one is.
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>
#include <cstring>
#include <utility>
#include <vector>

namespace radiant::render {
namespace {

bool hasExtension(const char* extensions, const char* name) {
    if (extensions == nullptr) return false;
    const std::size_t length = std::strlen(name);
    for (const char* at = std::strstr(extensions, name); at != nullptr; at = std::strstr(at + length, name))
        if ((at == extensions || at[-1] == ' ') && (at[length] == ' ' || at[length] == '\0')) return true;
    return false;
}

std::string eglErrorText() {
    char code[16];
    std::snprintf(code, sizeof code, "0x%04x", static_cast<unsigned>(eglGetError()));
    return std::string("EGL error ") + code;
}

template <class Function>
Function eglFunction(const char* name) {
    // eglGetProcAddress returns a generic function pointer; the cast to its real type is the EGL contract.
    return reinterpret_cast<Function>(eglGetProcAddress(name));
}

/// The surfaceless platform first (Mesa, any GPU or llvmpipe), then the first EGL device.
EGLDisplay openDisplay(std::string& platform, std::string& whyNot) {
    const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (clientExtensions == nullptr) {
        whyNot = "EGL has no client extensions (" + eglErrorText() + ")";
        return EGL_NO_DISPLAY;
    }
    const auto getPlatformDisplay = eglFunction<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
    if (getPlatformDisplay == nullptr) {
        whyNot = "EGL lacks eglGetPlatformDisplayEXT";
        return EGL_NO_DISPLAY;
    }
    if (hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless")) {
        EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (display != EGL_NO_DISPLAY) {
            platform = "surfaceless";
            return display;
        }
    }
    if (hasExtension(clientExtensions, "EGL_EXT_platform_device")) {
        const auto queryDevices = eglFunction<PFNEGLQUERYDEVICESEXTPROC>("eglQueryDevicesEXT");
        EGLDeviceEXT device = nullptr;
        EGLint count = 0;
        if (queryDevices != nullptr && queryDevices(1, &device, &count) == EGL_TRUE && count > 0) {
            EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
            if (display != EGL_NO_DISPLAY) {
                platform = "device";
                return display;
            }
        }
    }
    whyNot = "EGL offers neither the surfaceless platform nor a device";
    return EGL_NO_DISPLAY;
}

} // namespace

std::unique_ptr<HeadlessGlContext> HeadlessGlContext::tryCreate(std::string& whyNot) {
    std::unique_ptr<HeadlessGlContext> result(new HeadlessGlContext());
    EGLDisplay display = openDisplay(result->platform_, whyNot);
    if (display == EGL_NO_DISPLAY) return nullptr;
    EGLint major = 0, minor = 0;
    if (eglInitialize(display, &major, &minor) != EGL_TRUE) {
        whyNot = "eglInitialize failed on the " + result->platform_ + " platform (" + eglErrorText() + ")";
        return nullptr;
    }
    result->display_ = display;  // from here the destructor terminates it
    // No surface at all: drawing goes to framebuffer objects, which needs surfaceless contexts.
    if (!hasExtension(eglQueryString(display, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context")) {
        whyNot = "the EGL display lacks EGL_KHR_surfaceless_context";
        return nullptr;
    }
    if (eglBindAPI(EGL_OPENGL_API) != EGL_TRUE) {
        whyNot = "EGL cannot bind desktop OpenGL (" + eglErrorText() + ")";
        return nullptr;
    }
    // Any surface type: the default (window) matches nothing on the surfaceless platform.
    const EGLint configAttributes[] = {EGL_SURFACE_TYPE, 0, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint configCount = 0;
    if (eglChooseConfig(display, configAttributes, &config, 1, &configCount) != EGL_TRUE || configCount < 1) {
        whyNot = "no EGL config renders desktop OpenGL";
        return nullptr;
    }
    std::string firstError;
    for (const auto& [wantedMajor, wantedMinor] : {std::pair{4, 5}, std::pair{3, 3}}) {
        const EGLint contextAttributes[] = {EGL_CONTEXT_MAJOR_VERSION, wantedMajor, EGL_CONTEXT_MINOR_VERSION,
                                            wantedMinor, EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                            EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
        result->context_ = eglCreateContext(display, config, EGL_NO_CONTEXT, contextAttributes);
        if (result->context_ != EGL_NO_CONTEXT) break;
        if (firstError.empty()) firstError = eglErrorText();
    }
    if (result->context_ == EGL_NO_CONTEXT) {
        result->context_ = nullptr;
        whyNot = "no OpenGL 3.3+ core context through EGL (" + firstError + ")";
        return nullptr;
    }
    if (eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, result->context_) != EGL_TRUE) {
        whyNot = "eglMakeCurrent without a surface failed (" + eglErrorText() + ")";
        return nullptr;
    }
    return result;
}

HeadlessGlContext::~HeadlessGlContext() {
    if (display_ == nullptr) return;
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (context_ != nullptr) eglDestroyContext(display_, context_);
    // No eglTerminate: the display is one per process anyway (eglGetPlatformDisplay returns the same
    // handle, and initialising it again is a no-op), and terminating unloads Mesa's driver, whose few
    // blocks kept until exit then show as a leak in "<unknown module>" that LeakSanitizer cannot
    // suppress (measured: 128 bytes; none with the driver kept loaded, as tests/gl does for GLX).
}

} // namespace radiant::render
