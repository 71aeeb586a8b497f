// A GLFW window with a 4.5 core context. A machine without 4.5 gets a message naming what it
// offers (found by asking GLFW for any context), not a crash.
#include "platform/context.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "base/log.hpp"
#include "gl/context_guard.hpp"

namespace fx {
namespace {

std::string lastGlfwError() {
    const char* description = nullptr;
    int code = glfwGetError(&description);
    return code == GLFW_NO_ERROR ? std::string("no error reported")
                                 : cat(description ? description : "", " (", code, ")");
}

// What the machine can do when 4.5 core is refused: any context at all, for the message.
std::string describeBestAvailableContext() {
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
    GLFWwindow* probe = glfwCreateWindow(16, 16, "fxlab probe", nullptr, nullptr);
    if (!probe) return "no OpenGL context at all (" + lastGlfwError() + ")";
    glfwMakeContextCurrent(probe);
    auto getString =
        reinterpret_cast<const unsigned char* (*)(unsigned int)>(glfwGetProcAddress("glGetString"));
    std::string text = "an unknown version";
    if (getString) {
        const auto* version = getString(GL_VERSION);
        const auto* renderer = getString(GL_RENDERER);
        text = cat("OpenGL ", version ? reinterpret_cast<const char*>(version) : "?", " on ",
                   renderer ? reinterpret_cast<const char*>(renderer) : "?");
    }
    glfwMakeContextCurrent(nullptr);
    glfwDestroyWindow(probe);
    return text;
}

class GlfwContext final : public Context {
public:
    explicit GlfwContext(GLFWwindow* window) : window_(window) {}
    ~GlfwContext() override {
        gl::setContextAlive(false);
        glfwDestroyWindow(window_);
        glfwTerminate();
    }

    Size2D framebufferSize() const override {
        Size2D e;
        glfwGetFramebufferSize(window_, &e.width, &e.height);
        return e;
    }
    GLuint presentFramebuffer() const override { return 0; }
    void present() override { glfwSwapBuffers(window_); }
    void pollEvents() override { glfwPollEvents(); }
    bool shouldClose() const override { return glfwWindowShouldClose(window_) != 0; }
    bool headless() const override { return false; }
    void resize(Size2D size) override {
        // X refuses a 0-wide window with a fatal BadValue: a size of 0 is the minimised window that
        // --resize 0x0 stands for, so ask the window system for that instead.
        if (size.empty()) {
            glfwIconifyWindow(window_);
            return;
        }
        if (glfwGetWindowAttrib(window_, GLFW_ICONIFIED) != 0) glfwRestoreWindow(window_);
        glfwSetWindowSize(window_, size.width, size.height);
    }
    GLFWwindow* window() const override { return window_; }
    bool hidden() const override {
        return glfwGetWindowAttrib(window_, GLFW_ICONIFIED) != 0 ||
               glfwGetWindowAttrib(window_, GLFW_VISIBLE) == 0;
    }
    void waitEvents(double seconds) override { glfwWaitEventsTimeout(seconds); }

    Status setup() { return finishSetup("GLFW window"); }

private:
    GLFWwindow* window_;
};

}  // namespace

Result<std::unique_ptr<Context>> createWindowContext(const ContextOptions& options) {
    if (!glfwInit()) return Error{"GLFW could not start: " + lastGlfwError()};
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, options.debugContext ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_VISIBLE, options.visible ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_SRGB_CAPABLE, GLFW_FALSE);
    GLFWwindow* window =
        glfwCreateWindow(options.size.width, options.size.height, options.title.c_str(), nullptr, nullptr);
    if (!window) {
        std::string reason = lastGlfwError();
        std::string found = describeBestAvailableContext();
        glfwTerminate();
        return Error{cat("fxlab needs OpenGL 4.5 core; the window system refused it (", reason,
                         "); this machine offers ", found)};
    }
    glfwMakeContextCurrent(window);
    glfwSwapInterval(1);
    if (!gladLoadGL(glfwGetProcAddress)) {
        glfwDestroyWindow(window);
        glfwTerminate();
        return Error{"glad could not load OpenGL functions from the GLFW context"};
    }
    auto context = std::make_unique<GlfwContext>(window);
    if (auto status = context->setup(); !status) return Error{status.error()};
    return std::unique_ptr<Context>(std::move(context));
}

}  // namespace fx
