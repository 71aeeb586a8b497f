// Headless OpenGL on Windows, which has no EGL: a hidden GLFW window holds a 4.5 core context, and,
// as with EGL (egl_context.cpp, the POSIX twin), the presented image is an offscreen framebuffer
// (RGBA8 + depth) that captures read back, so a headless run draws the same pictures at the same size
// whatever the window system does with a window nobody sees.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "base/log.hpp"
#include "gl/context_guard.hpp"
#include "gl/framebuffer.hpp"
#include "platform/context.hpp"

namespace fx {
namespace {

std::string lastGlfwError() {
    const char* description = nullptr;
    int code = glfwGetError(&description);
    return code == GLFW_NO_ERROR ? std::string("no error reported")
                                 : cat(description ? description : "", " (", code, ")");
}

class HiddenWindowContext final : public Context {
public:
    explicit HiddenWindowContext(GLFWwindow* window) : window_(window) {}
    ~HiddenWindowContext() override {
        target_ = {};  // GL objects first, while the context is still current
        gl::setContextAlive(false);
        glfwDestroyWindow(window_);
        glfwTerminate();
    }

    Status setup(Size2D size) {
        if (auto status = finishSetup("hidden GLFW window (WGL)"); !status) return status;
        resize(size);
        return Status::success();
    }

    Size2D framebufferSize() const override { return size_; }
    GLuint presentFramebuffer() const override { return target_.framebuffer.name(); }
    void present() override { glFlush(); }
    void pollEvents() override {}
    bool shouldClose() const override { return false; }
    bool headless() const override { return true; }
    void resize(Size2D size) override {
        size_ = {std::max(size.width, 0), std::max(size.height, 0)};
        if (size_.empty()) return;  // like a minimised window: nothing is drawn
        target_ = gl::ColorDepthTarget::create(size_.width, size_.height, "present", "present (headless)");
    }

private:
    GLFWwindow* window_;
    Size2D size_;
    gl::ColorDepthTarget target_;
};

}  // namespace

Result<std::unique_ptr<Context>> createHeadlessContext(const ContextOptions& options) {
    if (!glfwInit()) return Error{"GLFW could not start: " + lastGlfwError()};
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, options.debugContext ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
    glfwWindowHint(GLFW_SRGB_CAPABLE, GLFW_FALSE);
    // The window's own buffer is never drawn into: the smallest the window system gives.
    GLFWwindow* window = glfwCreateWindow(16, 16, options.title.c_str(), nullptr, nullptr);
    if (!window) {
        const std::string reason = lastGlfwError();
        glfwTerminate();
        return Error{cat("fxlab needs OpenGL 4.5 core, and no hidden window could hold one (", reason,
                         "); update the graphics driver")};
    }
    glfwMakeContextCurrent(window);
    glfwSwapInterval(0);
    if (!gladLoadGL(glfwGetProcAddress)) {
        glfwDestroyWindow(window);
        glfwTerminate();
        return Error{"glad could not load OpenGL functions from the hidden window's context"};
    }
    auto context = std::make_unique<HiddenWindowContext>(window);
    if (auto status = context->setup(options.size); !status) return Error{status.error()};
    return std::unique_ptr<Context>(std::move(context));
}

}  // namespace fx
