#pragma once
// One GL context interface with two implementations: a GLFW window, and EGL headless (Mesa
// surfaceless, the EGL device platform for NVIDIA, or a pbuffer). Lessons never see which one runs:
// they draw into presentFramebuffer() at framebufferSize().
#include <memory>
#include <string>

#include "base/result.hpp"
#include "base/size2d.hpp"
#include "gl/gl.hpp"

struct GLFWwindow;

namespace fx {

struct ContextOptions {
    Size2D size{1280, 720};
    std::string title = "fxlab";
    bool debugContext = true;  // KHR_debug messages are delivered reliably only in debug contexts
    bool visible = true;       // windows only
};

class Context {
public:
    virtual ~Context() = default;

    // The size of what is presented; 0x0 while a window is minimised (render nothing then).
    virtual Size2D framebufferSize() const = 0;
    // 0 for a window's back buffer; an offscreen framebuffer when headless.
    virtual GLuint presentFramebuffer() const = 0;
    virtual void present() = 0;
    virtual void pollEvents() = 0;
    virtual bool shouldClose() const = 0;
    virtual bool headless() const = 0;
    // Headless contexts resize their offscreen target on request; windows follow the user.
    virtual void resize(Size2D size) = 0;
    virtual GLFWwindow* window() const { return nullptr; }
    // A window that is minimised or unmapped: nothing of it is seen. Headless: never.
    virtual bool hidden() const { return false; }
    // Sleeps until the window system has an event for the window, or `seconds` pass (a hidden window
    // waits here instead of rendering frames nobody sees). Headless: returns at once.
    virtual void waitEvents(double /*seconds*/) {}

    // "EGL surfaceless (Mesa)", "GLFW window" ...
    const std::string& kind() const { return kind_; }
    // GL_RENDERER and GL_VERSION of the context.
    const std::string& renderer() const { return renderer_; }
    const std::string& version() const { return version_; }

protected:
    // After the context is current and GL is loaded: checks for 4.5 and fills renderer/version.
    Status finishSetup(std::string kind);
    std::string kind_, renderer_, version_;
};

Result<std::unique_ptr<Context>> createWindowContext(const ContextOptions& options);
Result<std::unique_ptr<Context>> createHeadlessContext(const ContextOptions& options);

// True when a window system is reachable (Linux: $DISPLAY or $WAYLAND_DISPLAY set; Windows: always,
// its headless context being a hidden GLFW window: platform/headless_context_win.cpp).
bool displayAvailable();

}  // namespace fx
