// Windows' headless context is a hidden GLFW window (platform/headless_context_win.cpp): GLFW loads
// from whichever context is current.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "ui/headless_gl_loader.hpp"

namespace fx {

bool headlessContextCurrent() {
    return glfwGetCurrentContext() != nullptr;
}

HeadlessGlProc headlessGlProc(const char* name) {
    return reinterpret_cast<HeadlessGlProc>(glfwGetProcAddress(name));
}

}  // namespace fx
