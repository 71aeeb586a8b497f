#pragma once
// The frame graph on GL as a lesson's runner sets it up, for the GL tests: a texture allocator and its
// pool, a pass timer (off unless a test times its passes), the executor, and an output texture
// ("test.output") that the graph's presenting passes draw into. Every harness builds on this one, so
// a change in how a lesson runs its graph reaches every test at once.
//
//   GlFrameRunner runner({8, 4});
//   FloatImage out = runner.frameAndRead([&](FrameGraph& g) { return effect.declare(g, ...).output; });
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "gl/framebuffer.hpp"
#include "gl/readback.hpp"
#include "gl/texture.hpp"
#include "image/image.hpp"
#include "render/frame_graph.hpp"
#include "render/texture_pool.hpp"
#include "render_gl/gl_pass_executor.hpp"
#include "render_gl/gl_texture_allocator.hpp"
#include "render_gl/pass_timer.hpp"

namespace fx::test {

// The tests share one context: leave it as GL starts, so a later test that relies on the defaults
// (depth writes on, say) does not inherit a pass's state (Shader effects, hard case 15).
inline void restoreInitialState() {
    glDepthMask(GL_TRUE);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glUseProgram(0);
    glBindVertexArray(0);
}

class GlFrameRunner {
public:
    explicit GlFrameRunner(Size2D outputSize, TimingMode timing = TimingMode::Off)
        : timer(timing,
                timing == TimingMode::Off ? "" : reinterpret_cast<const char*>(glGetString(GL_RENDERER))),
          executor(timer, {0, true}),
          size_(outputSize),
          output_(gl::Texture::create2D(TextureFormat::RGBA8, outputSize.width, outputSize.height, 1,
                                        "test.output")),
          outputFbo_("test.output") {
        outputFbo_.attachColor(0, output_);
        outputFbo_.setDrawBuffers(1);
        executor.setPresentFramebuffer(outputFbo_.name());
    }

    // One frame on a fresh graph of the output's size: `declare` adds the passes, the graph runs,
    // `whileHeld` sees its textures (the report, read-backs) before they go back to the pool; then the
    // pool's frame ends and GL is in its initial state again. A graph that fails to run fails the test
    // (no GL test runs a broken graph on purpose through here); its error is also kept in lastError.
    Status frame(const std::function<void(FrameGraph&)>& declare,
                 const std::function<void(FrameGraph&)>& whileHeld = {}) {
        FrameGraph graph(OutputTarget{size_, "output", TextureFormat::RGBA8, 0});
        declare(graph);
        Status status = graph.execute(pool, executor);
        lastError = status ? std::string() : status.error();
        EXPECT_TRUE(status) << lastError;
        report = graph.report();
        if (status && whileHeld) whileHeld(graph);
        graph.releaseTextures();
        pool.endFrame();
        restoreInitialState();
        return status;
    }

    // A frame whose `declare` returns the texture a test reads: captured (so it is not culled), run, and
    // read back as floats; empty when the graph failed or the texture is the presented output.
    FloatImage frameAndRead(const std::function<TextureHandle(FrameGraph&)>& declare) {
        TextureHandle result;
        FloatImage out;
        frame(
            [&](FrameGraph& graph) {
                result = declare(graph);
                graph.capture(result);
            },
            [&](FrameGraph& graph) {
                const TextureView& view = graph.texture(result);
                if (view.native != 0 && view.origin != TextureOrigin::PresentedOutput) {
                    out = gl::readTexture(view.native, view.spec, 0);
                }
            });
        return out;
    }

    // What the output texture holds after the last frame.
    ByteImage readOutput() const {
        return gl::readFramebufferRgba8(outputFbo_.name(), size_.width, size_.height);
    }
    GLuint outputFramebuffer() const { return outputFbo_.name(); }
    Size2D size() const { return size_; }

    GlTextureAllocator allocator;
    TexturePool pool{allocator};
    PassTimer timer;
    GlPassExecutor executor;
    FrameReport report;     // the last frame's
    std::string lastError;  // the last frame's, empty when it ran

private:
    Size2D size_;
    gl::Texture output_;
    gl::Framebuffer outputFbo_;
};

}  // namespace fx::test
