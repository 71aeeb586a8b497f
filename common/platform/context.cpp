#include "platform/context.hpp"

#include <cstring>

#include "base/log.hpp"
#include "gl/context_guard.hpp"
#include "gl/debug_output.hpp"

namespace fx {

Status Context::finishSetup(std::string kind) {
    kind_ = std::move(kind);
    auto text = [](GLenum what) {
        const auto* s = reinterpret_cast<const char*>(glGetString(what));
        return std::string(s ? s : "(unknown)");
    };
    renderer_ = text(GL_RENDERER);
    version_ = text(GL_VERSION);
    GLint major = 0, minor = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    if (major < 4 || (major == 4 && minor < 5)) {
        return Error{cat("fxlab needs OpenGL 4.5 core; this machine offers OpenGL ", version_, " on ",
                         renderer_, " (", kind_,
                         "). Update the graphics driver, or use Mesa's llvmpipe (LIBGL_ALWAYS_SOFTWARE=1).")};
    }
    gl::setContextAlive(true);
    gl::installDebugOutput();
    log::info("OpenGL ", version_, " on ", renderer_, " (", kind_, ")");
    return Status::success();
}

}  // namespace fx
