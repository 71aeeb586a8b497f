#include "effects/deferred/output_check.hpp"

#include <map>
#include <utility>

#include "base/log.hpp"
#include "gl/framebuffer.hpp"

namespace fx {

bool checkOutputsOnce(GLuint program, std::string_view pass) {
    GLint framebuffer = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
    // The answers so far; GL names can be reused after a reload, which at worst checks again.
    static std::map<std::pair<GLuint, GLuint>, bool> known;
    auto key = std::make_pair(program, GLuint(framebuffer));
    if (auto it = known.find(key); it != known.end()) return it->second;
    Status status =
        gl::checkProgramOutputs(program, GLuint(framebuffer), cat("the framebuffer of '", pass, "'"));
    if (!status) log::error("pass '", pass, "': ", status.error());
    known.emplace(key, bool(status));
    return bool(status);
}

}  // namespace fx
