#include "effects/post/colour_matrix.hpp"

#include <cmath>

#include <glm/gtc/type_ptr.hpp>

#include "effects/post/post_bindings.hpp"
#include "effects/scene/hdr_scene_pass.hpp"

namespace fx {

glm::vec3 ColourTransform::row(int channel) const {
    return {matrix[0][channel], matrix[1][channel], matrix[2][channel]};
}

ColourTransform ColourTransform::fromRows(const glm::vec3& red, const glm::vec3& green, const glm::vec3& blue,
                                          const glm::vec3& offset) {
    ColourTransform t;
    for (int c = 0; c < 3; ++c) t.matrix[c] = glm::vec3(red[c], green[c], blue[c]);
    t.offset = offset;
    return t;
}

ColourTransform ColourTransform::grayscale() {
    glm::vec3 luma(kLumaR, kLumaG, kLumaB);
    return fromRows(luma, luma, luma);
}

ColourTransform ColourTransform::sepia() {
    return fromRows({0.346f, 0.678f, 0.151f},   // red'   (sum 1.175)
                    {0.278f, 0.546f, 0.124f},   // green' (sum 0.948)
                    {0.196f, 0.385f, 0.089f});  // blue'  (sum 0.670)
}

ColourTransform ColourTransform::saturation(float amount) {
    // (1 - s) * grayscale + s * identity.
    ColourTransform t;
    glm::mat3 gray = grayscale().matrix;
    t.matrix = gray * (1.0f - amount) + glm::mat3(1.0f) * amount;
    return t;
}

ColourTransform ColourTransform::hueRotation(float degrees) {
    // Rotation about the unit grey axis k = (1, 1, 1) / sqrt(3) (Rodrigues):
    // R = cos(a) I + sin(a) [k]x + (1 - cos(a)) k k^T.
    double a = double(degrees) * 3.14159265358979323846 / 180.0;
    float c = float(std::cos(a)), s = float(std::sin(a));
    float k = 1.0f / std::sqrt(3.0f);
    float diagonal = c + (1.0f - c) / 3.0f;
    float shared = (1.0f - c) / 3.0f;
    return fromRows({diagonal, shared - s * k, shared + s * k}, {shared + s * k, diagonal, shared - s * k},
                    {shared - s * k, shared + s * k, diagonal});
}

ColourTransform ColourTransform::channelSwap(const std::array<int, 3>& source) {
    ColourTransform t;
    t.matrix = glm::mat3(0.0f);
    for (int out = 0; out < 3; ++out) {
        int in = source[std::size_t(out)];
        if (in >= 0 && in < 3) t.matrix[in][out] = 1.0f;
    }
    return t;
}

ColourTransform ColourTransform::brightnessContrast(float brightness, float contrast) {
    // c' = (c - g) * k + g + b = k c + ((1 - k) g + b).
    ColourTransform t;
    t.matrix = glm::mat3(contrast);
    t.offset = glm::vec3((1.0f - contrast) * kMidGrey + brightness);
    return t;
}

ColourTransform ColourTransform::invert() {
    ColourTransform t;
    t.matrix = glm::mat3(-1.0f);
    t.offset = glm::vec3(1.0f);
    return t;
}

ColourTransform ColourTransform::negate() {
    ColourTransform t;
    t.matrix = glm::mat3(-1.0f);
    return t;
}

ColourTransform then(const ColourTransform& first, const ColourTransform& second) {
    ColourTransform t;
    t.matrix = second.matrix * first.matrix;
    t.offset = second.matrix * first.offset + second.offset;
    return t;
}

ColourTransform blendFromIdentity(const ColourTransform& t, float amount) {
    ColourTransform out;
    out.matrix = glm::mat3(1.0f) * (1.0f - amount) + t.matrix * amount;
    out.offset = t.offset * amount;
    return out;
}

DeclaredPass ColourMatrixPass::declare(FrameGraph& graph, TextureHandle input, TextureFormat format) const {
    const FullscreenPass* pass = &pass_;
    ColourTransform t = transform_;  // the transform as it is now, not when the pass runs
    Pass& declared = pass_.addPass(graph, "colour matrix", [pass, input, t](PassContext& ctx) {
        GLuint program = pass->program();
        // Column-major data, no transpose: uploading rows is Shader effects' hard case 7 (a
        // grayscale that comes out tinted).
        glProgramUniformMatrix3fv(program, glsl::kColourMatrixLocation, 1, GL_FALSE,
                                  glm::value_ptr(t.matrix));
        glProgramUniform3fv(program, glsl::kColourOffsetLocation, 1, glm::value_ptr(t.offset));
        glProgramUniform1f(program, glsl::kHdrMaxLocation, kSceneHdrMax);
        pass->draw({ctx.native(input)});
    });
    TextureHandle graded =
        declared.create("colour.graded", {TextureSize::output(), format, 1}, TextureUsage::ColorAttachment);
    declared.read(input).setTaps(1);
    return {declared, graded};
}

}  // namespace fx
