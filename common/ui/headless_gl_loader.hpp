#pragma once
// The GL entry points of the headless context, for the overlay's loader (imgui_backend.cpp): EGL's on
// Linux (headless_gl_loader_posix.cpp), the hidden GLFW window's on Windows (headless_gl_loader_win.cpp).
namespace fx {

using HeadlessGlProc = void (*)();
// Whether a headless context is current (one can load GL through it).
bool headlessContextCurrent();
HeadlessGlProc headlessGlProc(const char* name);

}  // namespace fx
