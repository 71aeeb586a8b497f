#include "effects/bloom/bloom_composite.hpp"

#include <algorithm>
#include <functional>

namespace fx {

float averagedCompositeScale(int levels) {
    return 1.0f / float(std::max(levels, 1));
}

float normalisedCompositeScale(float intensity, int levels) {
    return intensity / float(std::max(levels, 1));
}

namespace {

// The glow's filter as the shaders number it: filter 2 in shaders/effects/bloom/bloom_common.glsl is one
// bilinear tap of a glow blurred already.
int compositeFilters(const BloomCompositeSettings& settings) {
    return settings.filters ? static_cast<int>(*settings.filters) : 2;
}

// The composite's draw, fused or not: the glow's offset and scale, then scene and glow on units 0 and 1
// with the chain's sampler. `more` sets the uniforms only one of the two programs has.
Pass::Body compositeBody(const FullscreenPass* pass, const BloomSampler* sampler, TextureHandle scene,
                         TextureHandle glow, const BloomCompositeSettings& settings,
                         std::function<void(GLuint)> more) {
    return [=](PassContext& ctx) {
        GLuint p = pass->program();
        glProgramUniform1f(p, glsl::kBloomOffsetLocation, settings.upOffset);
        glProgramUniform1f(p, glsl::kBloomUpScaleLocation, settings.scale);
        more(p);
        sampler->bind();
        pass->draw({ctx.native(scene), ctx.native(glow)});
        BloomSampler::unbind();
    };
}

}  // namespace

DeclaredPass BloomComposite::declare(FrameGraph& graph, TextureHandle scene, TextureHandle glow,
                                     const BloomCompositeSettings& settings) const {
    const FullscreenPass& program =
        pass_.get({{"BLOOM_FILTERS", compositeFilters(settings)}, {"BLOOM_WIDE", 0}});
    Pass& composite = program.addPass(
        graph, "bloom composite", compositeBody(&program, &sampler_, scene, glow, settings, [](GLuint) {}));
    TextureHandle result = composite.create(
        "bloom.result", {TextureSize::output(), TextureFormat::RGBA16F, 1}, TextureUsage::ColorAttachment);
    composite.read(scene).read(glow).setTaps(1 + bloomUpsampleTaps(compositeFilters(settings)));
    return {composite, result};
}

Pass& BloomComposite::declarePresented(FrameGraph& graph, TextureHandle scene, TextureHandle glow,
                                       const BloomCompositeSettings& settings, ToneCurve curve,
                                       float exposure) const {
    const FullscreenPass& program = presented_.get(
        {{"BLOOM_FILTERS", compositeFilters(settings)}, {"TONE_CURVE", static_cast<int>(curve)}});
    Pass& declared = program.addPass(graph, "bloom composite + output transform",
                                     compositeBody(&program, &sampler_, scene, glow, settings, [=](GLuint p) {
                                         glProgramUniform1f(p, glsl::kBloomExposureLocation, exposure);
                                     }));
    declared.read(scene).read(glow).writeColor(graph.output());
    declared.setTaps(1 + bloomUpsampleTaps(compositeFilters(settings)));
    return declared;
}

}  // namespace fx
