#include "effects/bloom/bloom_reference.hpp"

#include <algorithm>
#include <cmath>

#include "base/log.hpp"
#include "effects/post/fullscreen_variants.hpp"

namespace fx {
namespace {

// shaders/effects/bloom/gaussian.frag
constexpr GLint kDirectionLocation = 0, kSigmaLocation = 1, kScaleLocation = 2;

}  // namespace

BloomReference BloomReference::create() {
    BloomReference r;
    // One texel of the same size (filter 2), no Karis average: the bright part exactly, per pixel.
    r.extract_ =
        FullscreenPass("effects/bloom/extract.frag", "bloom reference bright pass",
                       bloomShaderDefines() + shaderDefines({{"BLOOM_FILTERS", 2}, {"BLOOM_KARIS", 0}}));
    r.gaussian_ = FullscreenPass("effects/bloom/gaussian.frag", "bloom reference Gaussian");
    return r;
}

BloomReference::Declared BloomReference::declare(FrameGraph& graph, TextureHandle input,
                                                 const BloomReferenceSettings& settings) const {
    Declared d;
    if (graph.outputSize().empty() || settings.sigmas.empty()) return d;
    const TextureDesc full{TextureSize::output(), TextureFormat::RGBA32F, 1};
    std::string broken = usable() ? std::string() : "a bloom reference program did not build: " + error();

    const FullscreenPass* extract = &extract_;
    Pass& bright = graph.addPass("bloom reference bright", [=](PassContext& ctx) {
        GLuint p = extract->program();
        glProgramUniform1f(p, bloom_uniform::threshold, settings.threshold);
        glProgramUniform1f(p, bloom_uniform::knee, settings.knee);
        glProgramUniform1f(p, bloom_uniform::scale, 1.0f);
        glProgramUniform1f(p, bloom_uniform::offset, 0.0f);
        extract->draw({ctx.native(input)});
    });
    d.bright = bright.create("bloom.reference.bright", full, TextureUsage::ColorAttachment);
    bright.read(input).setState(FullscreenPass::state()).setTaps(1);
    d.passes.push_back(&bright);

    const FullscreenPass* gaussian = &gaussian_;
    auto blur = [gaussian](GLuint source, int dx, int dy, double sigma, float scale) {
        GLuint p = gaussian->program();
        glProgramUniform2i(p, kDirectionLocation, dx, dy);
        glProgramUniform1f(p, kSigmaLocation, float(sigma));
        glProgramUniform1f(p, kScaleLocation, scale);
        gaussian->draw({source});
    };
    d.glow = graph.declareTexture("bloom.reference", full);
    for (std::size_t k = 0; k < settings.sigmas.size(); ++k) {
        double sigma = settings.sigmas[k];
        const double taps = 2 * std::min(std::ceil(3.0 * sigma), 512.0) + 1;  // gaussian.frag's loop
        TextureHandle source = d.bright;
        Pass& x = graph.addPass(cat("bloom reference x ", k),
                                [=](PassContext& ctx) { blur(ctx.native(source), 1, 0, sigma, 1.0f); });
        TextureHandle blurred =
            x.create(cat("bloom.reference.blur_x[", k, "]"), full, TextureUsage::ColorAttachment);
        x.read(source).setState(FullscreenPass::state()).setTaps(taps);
        float weight = settings.levelWeight;
        Pass& y = graph.addPass(cat("bloom reference y ", k),
                                [=](PassContext& ctx) { blur(ctx.native(blurred), 0, 1, sigma, weight); });
        y.read(blurred).setTaps(taps);
        PassState state = FullscreenPass::state();
        if (k == 0) {
            // The first level clears the sum (alpha 1; the Gaussian writes alpha 0) and adds onto it.
            y.writeColor(d.glow);
            state.clearColor = ClearColor{0.0f, 0.0f, 0.0f, 1.0f};
        } else {
            y.modify(d.glow, TextureUsage::ColorAttachment);
        }
        state.blend = true;
        state.blendFunction = BlendFunction::additive();
        y.setState(state);
        d.passes.push_back(&x);
        d.passes.push_back(&y);
    }
    if (!broken.empty()) {
        for (Pass* p : d.passes) p->disable(broken);
    }
    return d;
}

}  // namespace fx
