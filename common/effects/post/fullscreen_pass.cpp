#include "effects/post/fullscreen_pass.hpp"

#include <utility>

#include "render_gl/program_pass.hpp"

namespace fx {

FullscreenPass::FullscreenPass(std::string fragmentShader, std::string label, std::string defines)
    : program_({"common/fullscreen.vert", std::move(fragmentShader), {}, std::move(defines), label}),
      triangle_(gl::createVertexArray(label + " (full-screen triangle)")) {}

Pass& FullscreenPass::addPass(FrameGraph& graph, std::string name, Pass::Body body) const {
    return runsWith(graph.addPass(std::move(name), std::move(body)).setState(state()), program_);
}

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
