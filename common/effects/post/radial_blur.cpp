#include "effects/post/radial_blur.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "effects/post/post_bindings.hpp"

namespace fx {
namespace {

const RadialBlurFormulaInfo kFormulas[] = {
    {"first version", "v = (centre - uv) * length", false},
    {"the chapter's start distance", "v = d * (max(|d| - start, 0) / |d|) * length: 0/0 at the centre pixel",
     true},
    {"guarded", "v = |d| > eps ? d * (max(|d| - start, 0) / |d|) * length : 0", false},
};

// `params` has been through clampedRadialBlurParams.
void setUniforms(GLuint program, const RadialBlurParams& params, Size2D size) {
    glm::vec2 centre = radialBlurCentrePixels(params, size);
    glProgramUniform2f(program, glsl::kBlurCentreLocation, centre.x, centre.y);
    glProgramUniform1f(program, glsl::kBlurLengthLocation, params.length);
    glProgramUniform1f(program, glsl::kBlurStartLocation, params.start);
    glProgramUniform1i(program, glsl::kBlurFormulaLocation, static_cast<int>(params.formula));
    glProgramUniform2f(program, glsl::kBlurTargetSizeLocation, float(std::max(size.width, 1)),
                       float(std::max(size.height, 1)));
}

}  // namespace

const RadialBlurFormulaInfo& describe(RadialBlurFormula formula) {
    return kFormulas[std::clamp(static_cast<int>(formula), 0, 2)];
}

RadialBlurParams clampedRadialBlurParams(RadialBlurParams params) {
    if (!std::isfinite(params.length) || params.length < 0.0f) params.length = 0.0f;
    if (std::isnan(params.start) || params.start < 0.0f) params.start = 0.0f;
    params.samples = std::clamp(params.samples, 1, kRadialBlurMaxSamples);
    return params;
}

glm::vec2 radialBlurCentrePixels(const RadialBlurParams& params, Size2D size) {
    double x = double(params.centre.x) * size.width, y = double(params.centre.y) * size.height;
    if (params.centreOnPixel) {
        x = std::floor(x) + 0.5;
        y = std::floor(y) + 0.5;
    }
    return {float(x), float(y)};
}

glm::vec2 radialBlurTapOffset(const RadialBlurParams& asked, Size2D size, glm::vec2 pixel) {
    const RadialBlurParams params = clampedRadialBlurParams(asked);
    glm::vec2 extent(float(std::max(size.width, 1)), float(std::max(size.height, 1)));
    glm::vec2 d = (radialBlurCentrePixels(params, size) - pixel) / extent;
    if (params.formula == RadialBlurFormula::firstVersion) return d * params.length;
    float lenA = glm::length(d);
    float lenB = std::max(lenA - params.start, 0.0f);
    if (params.formula == RadialBlurFormula::chapter) return d * (lenB / lenA) * params.length;
    return lenA > kRadialBlurCentreEpsilon ? d * (lenB / lenA) * params.length : glm::vec2(0.0f);
}

RadialBlur::Declared RadialBlur::declare(FrameGraph& graph, TextureHandle input,
                                         const RadialBlurParams& asked, TextureFormat format) const {
    const RadialBlurParams params = clampedRadialBlurParams(asked);
    const FullscreenPass* blur = &blur_;
    const GLuint sampler = sampler_.name();
    Pass& blurPass = blur_.addPass(graph, "radial blur", [blur, input, params, sampler](PassContext& ctx) {
        setUniforms(blur->program(), params, ctx.targetSize());
        glProgramUniform1i(blur->program(), glsl::kBlurSamplesLocation, params.samples);
        glBindSampler(0, sampler);
        blur->draw({ctx.native(input)});
        glBindSampler(0, 0);  // unit 0 goes back to its textures' own parameters
    });
    TextureHandle result =
        blurPass.create("blur.result", {TextureSize::output(), format, 1}, TextureUsage::ColorAttachment);
    blurPass.read(input).setTaps(params.length > 0.0f ? params.samples : 1);

    const FullscreenPass* offsets = &offsets_;
    Pass& offsetPass = offsets_.addPass(graph, "radial blur offsets", [offsets, params](PassContext& ctx) {
        setUniforms(offsets->program(), params, ctx.targetSize());
        offsets->draw({});
    });
    TextureHandle offset = offsetPass.create("blur.offset", {TextureSize::output(), TextureFormat::RG16F, 1},
                                             TextureUsage::ColorAttachment);
    offsetPass.setTaps(0);
    return {{blurPass, result}, {offsetPass, offset}};
}

}  // namespace fx
