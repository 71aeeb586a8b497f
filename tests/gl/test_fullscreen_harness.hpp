#pragma once
// Runs an effect's passes on a synthetic input, through the frame graph on GL exactly as a lesson
// does, and reads the results back as floats (and the presented output as bytes). The input is a
// texture the test fills; the effect sees it as an imported texture named "test.input".
//
//   EffectRunner runner(8, 4);
//   FloatImage out = runner.run(input, TextureFormat::RGBA16F, [&](FrameGraph& g, TextureHandle in) {
//       return grading.declare(g, in).output;
//   });
#include <functional>
#include <string>

#include "gl/framebuffer.hpp"
#include "gl/readback.hpp"
#include "gl/texture.hpp"
#include "image/image.hpp"
#include "render/frame_graph.hpp"
#include "render_gl/gl_pass_executor.hpp"
#include "render_gl/gl_texture_allocator.hpp"

namespace fx::test {

// A value from an integer hash of (x, y, c), in [0, 1): patterned test input without fract(sin).
inline float hashedValue(int x, int y, int c) {
    std::uint32_t h =
        std::uint32_t(x) * 73856093u ^ std::uint32_t(y) * 19349663u ^ std::uint32_t(c) * 83492791u;
    h ^= h >> 16;
    h *= 0x7feb352du;
    h ^= h >> 15;
    h *= 0x846ca68bu;
    h ^= h >> 16;
    return float(h >> 8) / float(1u << 24);
}

// An RGBA float image filled by f(x, y) -> the texel's four values.
template <class F>
FloatImage makeImage(int width, int height, F f) {
    FloatImage image = makeFloatImage(width, height, 4);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            auto v = f(x, y);
            for (int c = 0; c < 4; ++c) image.texel(x, y, c) = v[std::size_t(c)];
        }
    }
    return image;
}

class EffectRunner {
public:
    using Declare = std::function<TextureHandle(FrameGraph&, TextureHandle input)>;

    EffectRunner(int width, int height)
        : width_(width),
          height_(height),
          timer_(TimingMode::Off, ""),
          executor_(timer_, {0, true}),
          output_(gl::Texture::create2D(TextureFormat::RGBA8, width, height, 1, "test.output")),
          outputFbo_("test.output") {
        outputFbo_.attachColor(0, output_);
        outputFbo_.setDrawBuffers(1);
        executor_.setPresentFramebuffer(outputFbo_.name());
    }

    // Uploads `input` into a texture of `format`, declares the effect on a fresh graph and runs it.
    // Returns the texture `declare` names, read back as floats (empty when the graph failed).
    FloatImage run(const FloatImage& input, TextureFormat format, const Declare& declare) {
        gl::Texture texture = gl::Texture::create2D(format, width_, height_, 1, "test.input");
        glTextureSubImage2D(texture.name(), 0, 0, 0, width_, height_, GL_RGBA, GL_FLOAT, input.texels.data());
        storedInput = gl::readTexture(texture);

        FrameGraph graph(OutputTarget{{width_, height_}, "output", TextureFormat::RGBA8, 0});
        TextureHandle in = graph.importTexture("test.input", {width_, height_, format, 1}, texture.name());
        TextureHandle result = declare(graph, in);
        graph.capture(result);
        FloatImage out;
        Status status = graph.execute(pool_, executor_);
        lastErrors = status ? std::string() : status.error();
        report = graph.report();
        if (status) {
            const TextureView& view = graph.texture(result);
            if (view.native != 0 && view.origin != TextureOrigin::PresentedOutput) {
                out = gl::readTexture(view.native, view.spec, 0);
            }
            presented = gl::readFramebufferRgba8(outputFbo_.name(), width_, height_);
        }
        graph.releaseTextures();
        pool_.endFrame();
        restoreInitialState();
        return out;
    }

    // The tests share one context: leave it as GL starts, so a later test that relies on the defaults
    // (depth writes on, say) does not inherit a full-screen pass's state (Shader effects, hard case 15).
    static void restoreInitialState() {
        glDepthMask(GL_TRUE);
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_BLEND);
        glDisable(GL_CULL_FACE);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glUseProgram(0);
        glBindVertexArray(0);
    }

    FloatImage storedInput;  // the input as the GPU stored it (rounded to the format)
    ByteImage presented;     // what the graph's output holds after the last run
    FrameReport report;
    std::string lastErrors;

private:
    int width_, height_;
    GlTextureAllocator allocator_;
    TexturePool pool_{allocator_};
    PassTimer timer_;
    GlPassExecutor executor_;
    gl::Texture output_;
    gl::Framebuffer outputFbo_;
};

}  // namespace fx::test
