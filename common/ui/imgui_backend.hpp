#pragma once
// Starting and stopping Dear ImGui's GLFW and OpenGL3 backends (Debian's imgui 1.86).
//
// The OpenGL3 backend does not use our loader: it loads its ~50 GL functions through its bundled
// gl3w loader, which dlopens libGL.so.1 and asks glXGetProcAddressARB. That works in the EGL
// headless context only because Debian's libGL.so.1 is libglvnd's: its GL entry points are
// libGLdispatch stubs that call into whichever vendor owns the thread's current context, EGL or
// GLX. A libGL that is not libglvnd (some proprietary or hand-built drivers) would hand out GLX-only
// functions that fail or crash under EGL. So after the backend starts, its function table is loaded
// again from the context's own loader (eglGetProcAddress headless, glfwGetProcAddress in a window),
// the same entry points glad gave the rest of fxlab; imgl3wInit2 is the bundled loader's public way
// to do that. If that reload fails, the table from libGL.so.1 stays (it was working).
struct GLFWwindow;

namespace fx {

struct ImGuiBackends {
    bool platform = false;  // the GLFW backend (windows only)
    bool renderer = false;  // the OpenGL3 backend: the overlay can draw
};

// Creates the ImGui context and starts the backends, logging what failed. window == nullptr:
// headless, no platform backend (the overlay sets the display size itself).
ImGuiBackends startImGui(GLFWwindow* window);
// Dear ImGui's backend makes its GL objects without labels (its program, vertex and index buffers,
// font texture, and a vertex array every frame). Call before ImGui::Render(): a draw callback, which
// the backend runs with its own objects bound, labels each new one ("Dear ImGui: ..."), so a debugger
// shows them by name from the frame they are made in. Its two shaders are deleted as soon as the
// program is linked, before anything of ours runs: they stay unnamed.
void labelImGuiObjectsThisFrame();
// Stops what started and destroys the context.
void stopImGui(const ImGuiBackends& started);

}  // namespace fx
