#pragma once
// Frames with the overlay for the UI tests: a real frame graph executed on GL into an offscreen
// "screen", the overlay drawn on top headless (as --overlay does), and the picture read back.
#include <functional>
#include <string>

#include "gl/framebuffer.hpp"
#include "gl/program.hpp"
#include "gl/readback.hpp"
#include "gl/texture.hpp"
#include "gl_frame_runner.hpp"
#include "gl_test.hpp"
#include "ui/overlay.hpp"

namespace fx::test {

// The screen is the runner's output ("test.output"), with pass timing on as in a window.
struct UiHarness : GlFrameRunner {
    int width, height;
    Overlay overlay{nullptr};

    UiHarness(int w, int h) : GlFrameRunner({w, h}, TimingMode::Fenced), width(w), height(h) {}

    // One frame as the runner makes it: a slice of the cost panel's sweep between frames when one is
    // asked for, else build, inspect what the overlay wants, execute, draw the overlay while the
    // textures are held (`model` gets the graph and report); then read the screen back.
    ByteImage frame(const std::function<void(FrameGraph&)>& build, OverlayModel model = {},
                    bool withOverlay = true, const std::function<void(const FrameGraph&)>& whileHeld = {}) {
        if (withOverlay && overlay.costPanel().measurePending()) {
            overlay.costPanel().runPending(model.measureKnobs);
            glBindFramebuffer(GL_FRAMEBUFFER, outputFramebuffer());
            glViewport(0, 0, width, height);
            model.frame = &report;
            model.graph = nullptr;
            overlay.draw(model, width, height, 1.0 / 60.0);
            return readOutput();
        }
        GlFrameRunner::frame(
            [&](FrameGraph& graph) {
                build(graph);
                if (withOverlay) {
                    for (auto& name : overlay.wantedTextures()) graph.inspect(name);
                }
            },
            [&](FrameGraph& graph) {
                if (whileHeld) whileHeld(graph);
                if (withOverlay) {
                    glBindFramebuffer(GL_FRAMEBUFFER, outputFramebuffer());
                    glViewport(0, 0, width, height);
                    model.frame = &report;
                    model.graph = &graph;
                    overlay.draw(model, width, height, 1.0 / 60.0);
                }
            });
        return readOutput();
    }
};

// The test picture (shaders/ui/test_scene.frag) and a pass that presents a texture with it.
struct TestScene {
    gl::Program program;
    gl::VertexArrayName vao = gl::createVertexArray("test.scene vao");

    TestScene() {
        auto built =
            gl::Program::build({"common/fullscreen.vert", "ui/test_scene.frag", {}, {}, "test.scene"});
        EXPECT_TRUE(built.ok()) << (built ? "" : built.error());
        if (built) program = std::move(*built);
    }

    void drawPattern(Size2D size) const {
        glProgramUniform1i(program.name(), 0, 0);
        glProgramUniform2f(program.name(), 1, float(size.width), float(size.height));
        glUseProgram(program.name());
        glBindVertexArray(vao.name());
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }

    void present(GLuint texture) const {
        glProgramUniform1i(program.name(), 0, 1);
        glBindTextureUnit(0, texture);
        glUseProgram(program.name());
        glBindVertexArray(vao.name());
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }

    // scene.hdr (RGBA16F, the output's size, every mip level), its mips built by a pass of their
    // own, and presented on the output.
    TextureHandle declare(FrameGraph& graph) const {
        auto& draw =
            graph.addPass("sky and rings", [this](PassContext& ctx) { drawPattern(ctx.targetSize()); });
        TextureHandle hdr =
            draw.create("scene.hdr", {TextureSize::output(), TextureFormat::RGBA16F, kFullMipChain},
                        TextureUsage::ColorAttachment);
        draw.setState({.depthTest = false, .blend = false, .faceCulling = false});
        graph.addPass("build mips", [hdr](PassContext& ctx) { glGenerateTextureMipmap(ctx.native(hdr)); })
            .modify(hdr, TextureUsage::Storage);
        graph.addPass("present", [this, hdr](PassContext& ctx) { present(ctx.native(hdr)); })
            .read(hdr)
            .writeColor(graph.output())
            .setState({.depthTest = false, .blend = false, .faceCulling = false});
        return hdr;
    }
};

}  // namespace fx::test
