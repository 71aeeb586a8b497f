#include "ui/imgui_backend.hpp"

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "base/log.hpp"
#include "gl/gl.hpp"
#include "ui/headless_gl_loader.hpp"

// The bundled loader's public entry point (imgui_impl_opengl3_loader.h). That header is not
// included here because its GL macros would replace glad's.
extern "C" {
typedef void (*GL3WglProc)(void);
typedef GL3WglProc (*GL3WGetProcAddressProc)(const char* proc);
int imgl3wInit2(GL3WGetProcAddressProc proc);
int imgl3wInit(void);
}

namespace fx {
namespace {

GL3WglProc fromHeadless(const char* name) {
    return reinterpret_cast<GL3WglProc>(headlessGlProc(name));
}
GL3WglProc fromGlfw(const char* name) {
    return reinterpret_cast<GL3WglProc>(glfwGetProcAddress(name));
}

// Points the backend at the context's own loader; see imgui_backend.hpp for why.
void useContextLoader(GLFWwindow* window) {
    GL3WGetProcAddressProc proc = window ? fromGlfw : fromHeadless;
    if (!window && !headlessContextCurrent()) return;
    if (imgl3wInit2(proc) != 0) {
        log::warning("the overlay could not load GL through the context's loader; using libGL.so.1's");
        (void)imgl3wInit();
    }
}

}  // namespace

ImGuiBackends startImGui(GLFWwindow* window) {
    ImGuiBackends started;
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // no imgui.ini beside the user's files
    ImGui::StyleColorsDark();
    ImGuiStyle& style = ImGui::GetStyle();
    style.WindowRounding = 4.0f;
    style.FrameRounding = 2.0f;
    style.Colors[ImGuiCol_WindowBg].w = 0.92f;
    if (window) {
        started.platform = ImGui_ImplGlfw_InitForOpenGL(window, true);
        if (!started.platform) {
            log::error("the overlay could not attach to the window");
            return started;
        }
    }
    started.renderer = ImGui_ImplOpenGL3_Init("#version 450 core");
    if (!started.renderer) {
        log::error(
            "the overlay's OpenGL renderer could not start (Dear ImGui's loader needs libGL.so.1, Debian package libgl1)");
        return started;
    }
    useContextLoader(window);
    return started;
}

void stopImGui(const ImGuiBackends& started) {
    if (started.renderer) ImGui_ImplOpenGL3_Shutdown();
    if (started.platform) ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
}

}  // namespace fx
