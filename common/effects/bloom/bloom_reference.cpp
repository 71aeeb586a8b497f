#include "effects/bloom/bloom_reference.hpp"

#include <algorithm>
#include <cmath>

#include "base/log.hpp"
#include "render_gl/program_pass.hpp"

namespace fx {

BloomReference::Declared BloomReference::declare(FrameGraph& graph, TextureHandle input,
                                                 const BloomReferenceSettings& settings) const {
    Declared d;
    if (graph.outputSize().empty() || settings.sigmas.empty()) return d;
    const TextureDesc full{TextureSize::output(), TextureFormat::RGBA32F, 1};

    const FullscreenPass* extract = &extract_;
    Pass& bright = extract_.addPass(graph, "bloom reference bright", [=](PassContext& ctx) {
        GLuint p = extract->program();
        glProgramUniform1f(p, glsl::kBloomThresholdLocation, settings.threshold);
        glProgramUniform1f(p, glsl::kBloomKneeLocation, settings.knee);
        glProgramUniform1f(p, glsl::kBloomScaleLocation, 1.0f);
        glProgramUniform1f(p, glsl::kBloomOffsetLocation, 0.0f);
        extract->draw({ctx.native(input)});
    });
    d.bright = bright.create("bloom.reference.bright", full, TextureUsage::ColorAttachment);
    bright.read(input).setTaps(1);
    d.passes.push_back(&bright);

    const FullscreenPass* gaussian = &gaussian_;
    auto blur = [gaussian](GLuint source, int dx, int dy, double sigma, float scale) {
        GLuint p = gaussian->program();
        glProgramUniform2i(p, glsl::kGaussianDirectionLocation, dx, dy);
        glProgramUniform1f(p, glsl::kGaussianSigmaLocation, float(sigma));
        glProgramUniform1f(p, glsl::kGaussianScaleLocation, scale);
        gaussian->draw({source});
    };
    d.glow = graph.declareTexture("bloom.reference", full);
    for (std::size_t k = 0; k < settings.sigmas.size(); ++k) {
        double sigma = settings.sigmas[k];
        const double taps = 2 * std::min(std::ceil(3.0 * sigma), 512.0) + 1;  // gaussian.frag's loop
        TextureHandle source = d.bright;
        Pass& x = gaussian_.addPass(graph, cat("bloom reference x ", k),
                                    [=](PassContext& ctx) { blur(ctx.native(source), 1, 0, sigma, 1.0f); });
        TextureHandle blurred =
            x.create(cat("bloom.reference.blur_x[", k, "]"), full, TextureUsage::ColorAttachment);
        x.read(source).setTaps(taps);
        float weight = settings.levelWeight;
        Pass& y = gaussian_.addPass(graph, cat("bloom reference y ", k), [=](PassContext& ctx) {
            blur(ctx.native(blurred), 0, 1, sigma, weight);
        });
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
    runTogether(d.passes);
    return d;
}

}  // namespace fx
