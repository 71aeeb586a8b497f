// glad's EGL loader (loaded by the headless context) for eglGetProcAddress.
#include <glad/egl.h>

#include "ui/headless_gl_loader.hpp"

namespace fx {

bool headlessContextCurrent() {
    return glad_eglGetProcAddress && eglGetCurrentContext() != EGL_NO_CONTEXT;
}

HeadlessGlProc headlessGlProc(const char* name) {
    return reinterpret_cast<HeadlessGlProc>(eglGetProcAddress(name));
}

}  // namespace fx
