#include "effects/post/fullscreen_pass.hpp"

#include <utility>

namespace fx {

FullscreenPass::FullscreenPass(std::string fragmentShader, std::string label, std::string defines)
    : program_({"common/fullscreen.vert", std::move(fragmentShader), {}, std::move(defines), label}),
      triangle_(gl::createVertexArray(label + " (full-screen triangle)")) {}

void FullscreenPass::draw(std::initializer_list<GLuint> textures) const {
    GLuint unit = 0;
    for (GLuint texture : textures) glBindTextureUnit(unit++, texture);
    glUseProgram(program_.name());
    glBindVertexArray(triangle_.name());
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

PassState FullscreenPass::state() {
    return {.depthTest = false,
            .depthWrite = false,
            .blend = false,
            .faceCulling = false,
            .colorMask = ColorMask{}};
}

}  // namespace fx
