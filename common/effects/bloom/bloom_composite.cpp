#include "effects/bloom/bloom_composite.hpp"

#include <algorithm>

namespace fx {

float chapter000CompositeScale(int levels) {
    return 1.0f / float(std::max(levels, 1));
}

float normalisedCompositeScale(float intensity, int levels) {
    return intensity / float(std::max(levels, 1));
}

BloomComposite BloomComposite::create() {
    BloomComposite c;
    c.pass_ = FullscreenPass("effects/bloom/upsample.frag", "bloom composite", bloomShaderDefines());
    c.presented_ = FullscreenPass("effects/bloom/composite_present.frag",
                                  "bloom composite + output transform", bloomShaderDefines());
    c.sampler_ = BloomSampler::create();
    return c;
}

DeclaredPass BloomComposite::declare(FrameGraph& graph, TextureHandle scene, TextureHandle glow,
                                     const BloomCompositeSettings& settings) const {
    const FullscreenPass* pass = &pass_;
    const BloomSampler* sampler = &sampler_;
    // Filter 2 in shaders/effects/bloom/upsample.frag: one tap, the glow already full size.
    int filters = settings.filters ? static_cast<int>(*settings.filters) : 2;
    Pass& composite = graph.addPass("bloom composite", [=](PassContext& ctx) {
        GLuint p = pass->program();
        glProgramUniform1i(p, bloom_uniform::filters, filters);
        glProgramUniform1f(p, bloom_uniform::offset, settings.upOffset);
        glProgramUniform1f(p, bloom_uniform::upScale, settings.scale);
        glProgramUniform1i(p, bloom_uniform::wide, 0);
        sampler->bind();
        pass->draw({ctx.native(scene), ctx.native(glow)});
        BloomSampler::unbind();
    });
    TextureHandle result = composite.create(
        "bloom.result", {TextureSize::output(), TextureFormat::RGBA16F, 1}, TextureUsage::ColorAttachment);
    composite.read(scene).read(glow).setState(FullscreenPass::state());
    if (!pass_.usable()) composite.disable("the bloom composite program did not build: " + pass_.error());
    return {composite, result};
}

Pass& BloomComposite::declarePresented(FrameGraph& graph, TextureHandle scene, TextureHandle glow,
                                       const BloomCompositeSettings& settings, ToneCurve curve,
                                       float exposure) const {
    const FullscreenPass* pass = &presented_;
    const BloomSampler* sampler = &sampler_;
    int filters = settings.filters ? static_cast<int>(*settings.filters) : 2;
    Pass& declared = graph.addPass("bloom composite + output transform", [=](PassContext& ctx) {
        GLuint p = pass->program();
        glProgramUniform1i(p, bloom_uniform::filters, filters);
        glProgramUniform1f(p, bloom_uniform::offset, settings.upOffset);
        glProgramUniform1f(p, bloom_uniform::upScale, settings.scale);
        glProgramUniform1i(p, bloom_uniform::curve, static_cast<int>(curve));
        glProgramUniform1f(p, bloom_uniform::exposure, exposure);
        sampler->bind();
        pass->draw({ctx.native(scene), ctx.native(glow)});
        BloomSampler::unbind();
    });
    declared.read(scene).read(glow).writeColor(graph.output()).setState(FullscreenPass::state());
    if (!presented_.usable())
        declared.disable("the fused bloom composite program did not build: " + presented_.error());
    return declared;
}

}  // namespace fx
