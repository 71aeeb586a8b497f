#pragma once
// The draw call every post effect shares: one triangle that covers the target (shaders/common/
// fullscreen.vert makes it from gl_VertexID, so it needs no vertex buffer) with a fragment program
// that reads the pass's input textures. The triangle is wound counter-clockwise and the state below
// turns culling off anyway, so a leaked glCullFace cannot make it vanish (Shader effects, hard case 15).
//
//   // A member (copy_), built in init; the body runs after buildFrame returns, so it copies what
//   // it uses: the pointer to the pass and the handle, never a reference to a local.
//   const FullscreenPass* copy = &copy_;
//   graph.addPass("colour matrix", [copy, input](PassContext& ctx) { copy->draw({ctx.native(input)}); })
//       .read(input).writeColor(output).setState(FullscreenPass::state());
#include <initializer_list>
#include <string>

#include "gl/program.hpp"
#include "render/pass.hpp"
#include "render/pass_state.hpp"

namespace fx {

// What an effect's declare() hands back: its pass (to switch off with a reason) and the texture it makes.
struct DeclaredPass {
    Pass& pass;
    TextureHandle output;
};

class FullscreenPass {
public:
    FullscreenPass() = default;  // empty: no GL yet (lessons are built before the context)
    // Builds the program from common/fullscreen.vert and `fragmentShader` (relative to shaders/).
    FullscreenPass(std::string fragmentShader, std::string label, std::string defines = {});

    bool usable() const { return program_.usable(); }
    const std::string& error() const { return program_.error(); }
    GLuint program() const { return program_.name(); }

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
