#pragma once
// The draw call every post effect shares: one triangle that covers the target (shaders/common/
// fullscreen.vert makes it from gl_VertexID, so it needs no vertex buffer) with a fragment program
// that reads the pass's input textures. The triangle is wound counter-clockwise and the state below
// turns culling off anyway, so a leaked glCullFace cannot make it vanish (Shader effects, hard case 15).
//
//   // A member (copy_); the body runs after buildFrame returns, so it copies what it uses: the
//   // pointer to the pass and the handle, never a reference to a local.
//   const FullscreenPass* copy = &copy_;
//   copy_.addPass(graph, "copy", [copy, input](PassContext& ctx) { copy->draw({ctx.native(input)}); })
//       .read(input).writeColor(output);
#include <initializer_list>
#include <string>

#include "gl/program.hpp"
#include "render/frame_graph.hpp"
#include "render/pass_state.hpp"

namespace fx {

// What an effect's declare() hands back: its pass (to switch off with a reason) and the texture it makes.
struct DeclaredPass {
    Pass& pass;
    TextureHandle output;
};

class FullscreenPass {
public:
    // Builds the program from common/fullscreen.vert and `fragmentShader` (relative to shaders/).
    FullscreenPass(std::string fragmentShader, std::string label, std::string defines = {});

    GLuint program() const { return program_.name(); }
    const gl::ReloadableProgram& reloadable() const { return program_; }

    // Adds a pass that draws with this program: the full-screen state() below, and switched off with
    // the program's error when it never built (render_gl/program_pass.hpp). `body` sets the uniforms
    // and calls draw().
    Pass& addPass(FrameGraph& graph, std::string name, Pass::Body body) const;

    // Binds `textures` to units 0, 1, ... in order, then draws the triangle with the program. The
    // caller has set the program's uniforms (glProgramUniform*, no bind needed).
    void draw(std::initializer_list<GLuint> textures) const;

    // What a full-screen pass depends on: no depth test or write, no blending, no culling, every
    // colour channel written. Each pass says so itself instead of trusting the pass before it.
    static PassState state();

private:
    gl::ReloadableProgram program_;
    gl::VertexArrayName triangle_;
};

}  // namespace fx
