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

#include "gl/readback.hpp"
#include "gl/texture.hpp"
#include "gl_frame_runner.hpp"
#include "image/image.hpp"

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

// An effect on a synthetic input: the input uploaded into a texture of the format asked for and
// imported as "test.input", the effect declared on it, the result read back. The last frame's report
// and error are the runner's (report, lastError).
class EffectRunner : public GlFrameRunner {
public:
    using Declare = std::function<TextureHandle(FrameGraph&, TextureHandle input)>;

    EffectRunner(int width, int height) : GlFrameRunner({width, height}) {}

    // Uploads `input` into a texture of `format`, declares the effect on a fresh graph and runs it.
    // Returns the texture `declare` names, read back as floats (empty when the graph failed).
    FloatImage run(const FloatImage& input, TextureFormat format, const Declare& declare) {
        const Size2D s = size();
        gl::Texture texture = gl::Texture::create2D(format, s.width, s.height, 1, "test.input");
        glTextureSubImage2D(texture.name(), 0, 0, 0, s.width, s.height, GL_RGBA, GL_FLOAT,
                            input.texels.data());
        storedInput = gl::readTexture(texture);
        FloatImage out = frameAndRead([&](FrameGraph& graph) {
            return declare(graph,
                           graph.importTexture("test.input", {s.width, s.height, format, 1}, texture.name()));
        });
        if (lastError.empty()) presented = readOutput();
        return out;
    }

    FloatImage storedInput;  // the input as the GPU stored it (rounded to the format)
    ByteImage presented;     // what the graph's output held after the last run that ran
};

}  // namespace fx::test
