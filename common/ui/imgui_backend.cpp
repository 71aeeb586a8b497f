#include "ui/imgui_backend.hpp"

#include <imgui.h>

#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>
#include <cstdint>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "base/log.hpp"
#include "gl/gl.hpp"
#include "gl/object.hpp"
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

// The backend's objects as last labelled: each is labelled when it first shows up (a new name is a new
// object: the font atlas is made again when the fonts change). Kept here rather than asked back with
// glGetObjectLabel, which a debugger may answer with a name of its own ("Buffer 172").
struct LabelledObjects {
    GLint program = 0, vertices = 0, indices = 0, font = 0;
};
LabelledObjects labelled;

void labelOnce(GLenum identifier, GLint name, GLint& last, const char* label) {
    if (name <= 0 || name == last) return;
    gl::labelObject(identifier, GLuint(name), label);
    last = name;
}

// Runs inside the backend's RenderDrawData, with its program, vertex array and buffers bound.
void labelBoundObjects(const ImDrawList*, const ImDrawCmd*) {
    GLint program = 0, vertexArray = 0, vertices = 0, indices = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &program);
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertexArray);
    glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &vertices);
    glGetIntegerv(GL_ELEMENT_ARRAY_BUFFER_BINDING, &indices);
    labelOnce(GL_PROGRAM, program, labelled.program, "Dear ImGui: program");
    labelOnce(GL_BUFFER, vertices, labelled.vertices, "Dear ImGui: vertices");
    labelOnce(GL_BUFFER, indices, labelled.indices, "Dear ImGui: indices");
    const auto font = GLint(reinterpret_cast<std::intptr_t>(ImGui::GetIO().Fonts->TexID));
    labelOnce(GL_TEXTURE, font, labelled.font, "Dear ImGui: font atlas");
    // The backend makes its vertex array anew every frame.
    if (vertexArray > 0)
        gl::labelObject(GL_VERTEX_ARRAY, GLuint(vertexArray), "Dear ImGui: vertex array (made every frame)");
}

}  // namespace

void labelImGuiObjectsThisFrame() {
    // The background list is drawn first; a list that holds only a callback is still drawn.
    ImGui::GetBackgroundDrawList()->AddCallback(labelBoundObjects, nullptr);
}

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
    labelled = {};  // a new overlay's objects are new objects
    if (started.renderer) ImGui_ImplOpenGL3_Shutdown();
    if (started.platform) ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
}

}  // namespace fx
