// Headless OpenGL through EGL, tried in this order: Mesa's surfaceless platform (llvmpipe on CI),
// the EGL device platform (NVIDIA without a display), then the default display with a pbuffer.
// There is no window, so the presented image is an offscreen framebuffer (RGBA8 + depth) that
// captures read back.
#include <glad/egl.h>

#include <cstring>
#include <vector>

#include "base/log.hpp"
#include "gl/context_guard.hpp"
#include "gl/debug_output.hpp"
#include "gl/framebuffer.hpp"
#include "gl/texture.hpp"
#include "platform/context.hpp"

namespace fx {
namespace {

std::string eglErrorName(EGLint error) {
    switch (error) {
        case EGL_SUCCESS:
            return "EGL_SUCCESS";
        case EGL_NOT_INITIALIZED:
            return "EGL_NOT_INITIALIZED";
        case EGL_BAD_ACCESS:
            return "EGL_BAD_ACCESS";
        case EGL_BAD_ALLOC:
            return "EGL_BAD_ALLOC";
        case EGL_BAD_ATTRIBUTE:
            return "EGL_BAD_ATTRIBUTE";
        case EGL_BAD_CONFIG:
            return "EGL_BAD_CONFIG";
        case EGL_BAD_CONTEXT:
            return "EGL_BAD_CONTEXT";
        case EGL_BAD_DISPLAY:
            return "EGL_BAD_DISPLAY";
        case EGL_BAD_MATCH:
            return "EGL_BAD_MATCH";
        case EGL_BAD_PARAMETER:
            return "EGL_BAD_PARAMETER";
        case EGL_BAD_SURFACE:
            return "EGL_BAD_SURFACE";
        default:
            return cat("EGL error 0x", std::hex, error);
    }
}

struct Candidate {
    EGLDisplay display = EGL_NO_DISPLAY;
    bool needsPbuffer = false;
    std::string kind;
};

class EglContext final : public Context {
public:
    EglContext(EGLDisplay display, EGLContext context, EGLSurface surface)
        : display_(display), context_(context), surface_(surface) {}

    ~EglContext() override {
        // GL objects first, while the context is still current.
        target_ = {};
        gl::setContextAlive(false);
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (surface_ != EGL_NO_SURFACE) eglDestroySurface(display_, surface_);
        eglDestroyContext(display_, context_);
        eglTerminate(display_);
    }

    Status setup(const std::string& kind, Size2D size) {
        if (auto status = finishSetup(kind); !status) return status;
        frameTerminator_ = findFrameTerminator();
        resize(size);
        return Status::success();
    }

    Size2D framebufferSize() const override { return size_; }
    GLuint presentFramebuffer() const override { return target_.framebuffer.name(); }
    // Nothing is presented headless; a debugger that offers GL_GREMEDY_frame_terminator (RenderDoc,
    // apitrace) is told here that a frame ended, which a swap would have told it.
    // RenderDoc, told so, reads the default framebuffer that a surfaceless context lacks
    // (GL_INVALID_FRAMEBUFFER_OPERATION): the frame's own errors are counted first, and the debugger's
    // are not the lesson's.
    void present() override {
        glFlush();
        if (!frameTerminator_) return;
        gl::drainErrorFlags();
        frameTerminator_();
        while (glGetError() != GL_NO_ERROR) {
        }
    }
    void pollEvents() override {}
    bool shouldClose() const override { return false; }
    bool headless() const override { return true; }
    void resize(Size2D size) override {
        size_ = {std::max(size.width, 0), std::max(size.height, 0)};
        if (size_.empty()) return;  // like a minimised window: nothing is drawn
        target_ = gl::ColorDepthTarget::create(size_.width, size_.height, "present", "present (headless)");
    }

private:
    using FrameTerminator = void (*)();
    static FrameTerminator findFrameTerminator() {
        GLint count = 0;
        glGetIntegerv(GL_NUM_EXTENSIONS, &count);
        for (GLint i = 0; i < count; ++i) {
            const auto* name = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, GLuint(i)));
            if (name && std::strcmp(name, "GL_GREMEDY_frame_terminator") == 0)
                return reinterpret_cast<FrameTerminator>(eglGetProcAddress("glFrameTerminatorGREMEDY"));
        }
        return nullptr;
    }

    FrameTerminator frameTerminator_ = nullptr;
    EGLDisplay display_;
    EGLContext context_;
    EGLSurface surface_;
    Size2D size_;
    gl::ColorDepthTarget target_;
};

std::vector<Candidate> candidateDisplays(std::string& notes) {
    std::vector<Candidate> found;
    if (GLAD_EGL_MESA_platform_surfaceless && GLAD_EGL_EXT_platform_base) {
        EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (d != EGL_NO_DISPLAY) found.push_back({d, false, "EGL surfaceless"});
    } else {
        notes += " no EGL_MESA_platform_surfaceless;";
    }
    if (GLAD_EGL_EXT_device_enumeration && GLAD_EGL_EXT_platform_device) {
        EGLDeviceEXT devices[8];
        EGLint count = 0;
        if (eglQueryDevicesEXT(8, devices, &count)) {
            for (EGLint i = 0; i < count; ++i) {
                EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
                if (d != EGL_NO_DISPLAY) found.push_back({d, false, cat("EGL device ", i)});
            }
        }
    } else {
        notes += " no EGL device platform;";
    }
    EGLDisplay d = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    if (d != EGL_NO_DISPLAY) found.push_back({d, true, "EGL default display with a pbuffer"});
    return found;
}

// When 4.5 core is refused: what the display does offer, for the message (any context at all).
std::string describeBestContext(EGLDisplay display, EGLConfig config) {
    EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, nullptr);
    if (context == EGL_NO_CONTEXT) return "no OpenGL context at all";
    std::string found = "an OpenGL context of unknown version";
    if (eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
        auto getString = reinterpret_cast<const GLubyte* (*)(GLenum)>(eglGetProcAddress("glGetString"));
        if (getString) {
            const GLubyte* version = getString(GL_VERSION);
            const GLubyte* renderer = getString(GL_RENDERER);
            found = cat("OpenGL ", version ? reinterpret_cast<const char*>(version) : "?", " on ",
                        renderer ? reinterpret_cast<const char*>(renderer) : "?");
        }
        eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    }
    eglDestroyContext(display, context);
    return found;
}

}  // namespace

Result<std::unique_ptr<Context>> createHeadlessContext(const ContextOptions& options) {
    // First load: client extensions only, no display yet.
    if (!gladLoaderLoadEGL(EGL_NO_DISPLAY)) {
        return Error{
            "headless rendering needs EGL (libEGL.so.1), which could not be loaded: install libegl1 and Mesa (libegl-mesa0)"};
    }
    std::string notes;
    std::string failures;
    for (const Candidate& candidate : candidateDisplays(notes)) {
        EGLint major = 0, minor = 0;
        if (!eglInitialize(candidate.display, &major, &minor)) {
            failures +=
                cat("\n  ", candidate.kind, ": eglInitialize failed (", eglErrorName(eglGetError()), ")");
            continue;
        }
        gladLoaderLoadEGL(candidate.display);  // display extensions and EGL 1.5 entry points
        std::string vendor = eglQueryString(candidate.display, EGL_VENDOR)
                                 ? eglQueryString(candidate.display, EGL_VENDOR)
                                 : "?";
        const EGLint configAttributes[] = {EGL_SURFACE_TYPE,
                                           candidate.needsPbuffer ? EGL_PBUFFER_BIT : 0,
                                           EGL_RENDERABLE_TYPE,
                                           EGL_OPENGL_BIT,
                                           EGL_RED_SIZE,
                                           8,
                                           EGL_GREEN_SIZE,
                                           8,
                                           EGL_BLUE_SIZE,
                                           8,
                                           EGL_NONE};
        EGLConfig config = nullptr;
        EGLint configCount = 0;
        if (!eglChooseConfig(candidate.display, configAttributes, &config, 1, &configCount) ||
            configCount == 0 || !eglBindAPI(EGL_OPENGL_API)) {
            failures += cat("\n  ", candidate.kind, " (", vendor, "): no OpenGL config");
            eglTerminate(candidate.display);
            continue;
        }
        const EGLint contextAttributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                            4,
                                            EGL_CONTEXT_MINOR_VERSION,
                                            5,
                                            EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                            EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                            EGL_CONTEXT_OPENGL_DEBUG,
                                            options.debugContext ? EGL_TRUE : EGL_FALSE,
                                            EGL_NONE};
        EGLContext context = eglCreateContext(candidate.display, config, EGL_NO_CONTEXT, contextAttributes);
        if (context == EGL_NO_CONTEXT) {
            std::string why = eglErrorName(eglGetError());
            failures += cat("\n  ", candidate.kind, " (", vendor, "): no OpenGL 4.5 core context (", why,
                            "); it offers ", describeBestContext(candidate.display, config));
            eglTerminate(candidate.display);
            continue;
        }
        EGLSurface surface = EGL_NO_SURFACE;
        if (candidate.needsPbuffer) {
            const EGLint pbufferAttributes[] = {EGL_WIDTH, 1, EGL_HEIGHT, 1, EGL_NONE};
            surface = eglCreatePbufferSurface(candidate.display, config, pbufferAttributes);
        }
        if (!eglMakeCurrent(candidate.display, surface, surface, context)) {
            failures += cat("\n  ", candidate.kind, " (", vendor, "): eglMakeCurrent failed (",
                            eglErrorName(eglGetError()), ")");
            if (surface != EGL_NO_SURFACE) eglDestroySurface(candidate.display, surface);
            eglDestroyContext(candidate.display, context);
            eglTerminate(candidate.display);
            continue;
        }
        if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(eglGetProcAddress))) {
            return Error{"glad could not load OpenGL functions through EGL"};
        }
        auto result = std::make_unique<EglContext>(candidate.display, context, surface);
        if (auto status = result->setup(cat(candidate.kind, " (", vendor, ")"), options.size); !status) {
            failures += cat("\n  ", status.error());
            continue;  // the destructor released this display
        }
        return std::unique_ptr<Context>(std::move(result));
    }
    return Error{cat("fxlab needs OpenGL 4.5 core, and no headless context could be created:",
                     failures.empty() ? " no EGL display found" : failures,
                     notes.empty() ? "" : cat("\n  (", notes, " )"))};
}

}  // namespace fx
