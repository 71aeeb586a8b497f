// The one output encode is the output transform's (Shader effects §3.4): if GL_FRAMEBUFFER_SRGB were
// on with an sRGB-capable framebuffer, GL would encode a second time on every write, the washed-out
// double gamma of lesson 03 with no shader to blame. fxlab never turns it on and never presents into
// an sRGB framebuffer: a probe lesson looks at the state its pass runs in, frame after frame, with the
// overlay drawn in between (headless EGL; the window asks GLFW for a framebuffer that is not
// sRGB-capable, GLFW_SRGB_CAPABLE false in platform/glfw_context.cpp).
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/runner.hpp"
#include "gl/gl.hpp"

namespace fx {
namespace {

struct Seen {
    int frames = 0;
    int srgbEnabledFrames = 0;
    int srgbEncodedFrames = 0;
};
Seen seen;

class SrgbProbeLesson final : public Lesson {
public:
    std::vector<std::string> steps() const override { return {"one"}; }
    Status init(const Scene&) override { return Status::success(); }
    void buildFrame(FrameGraph& graph, const FrameInfo&) override {
        graph
            .addPass("look at the output's state",
                     [](PassContext&) {
                         ++seen.frames;
                         if (glIsEnabled(GL_FRAMEBUFFER_SRGB)) ++seen.srgbEnabledFrames;
                         GLint bound = 0;
                         glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &bound);
                         GLint encoding = GL_LINEAR;
                         glGetFramebufferAttachmentParameteriv(
                             GL_DRAW_FRAMEBUFFER, bound ? GL_COLOR_ATTACHMENT0 : GL_BACK_LEFT,
                             GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING, &encoding);
                         if (encoding == GL_SRGB) ++seen.srgbEncodedFrames;
                     })
            .writeColor(graph.output())
            .setState({.clearColor = ClearColor{0.5f, 0.5f, 0.5f, 1}});
    }
};

TEST(NoSrgbFramebuffer, TheOutputIsNeverEncodedByGl) {
    seen = {};
    std::vector<std::string> args = {"probe", "--headless", "--overlay", "--frames", "3", "--size", "32x32"};
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    ASSERT_EQ(runLesson<SrgbProbeLesson>({0, "srgb-probe", "sRGB probe", ""}, int(argv.size()), argv.data()),
              0);
    EXPECT_EQ(seen.frames, 3);
    EXPECT_EQ(seen.srgbEnabledFrames, 0) << "GL_FRAMEBUFFER_SRGB was on: GL would encode a second time";
    EXPECT_EQ(seen.srgbEncodedFrames, 0) << "the presented framebuffer is sRGB-encoded";
}

}  // namespace
}  // namespace fx
