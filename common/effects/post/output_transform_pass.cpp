#include "effects/post/output_transform_pass.hpp"

#include <algorithm>
#include <cmath>

#include "effects/post/post_bindings.hpp"

namespace fx {

const char* toString(ToneCurve curve) {
    switch (curve) {
        case ToneCurve::reinhard:
            return "Reinhard";
        case ToneCurve::filmic:
            return "ACES-style filmic";
        default:
            return "none (clip)";
    }
}

float applyToneCurve(ToneCurve curve, float x) {
    x = std::isnan(x) ? 0.0f : std::clamp(x, 0.0f, 65504.0f);
    switch (curve) {
        case ToneCurve::reinhard:
            return x / (1.0f + x);
        case ToneCurve::filmic:
            return std::clamp(x * (2.51f * x + 0.03f) / (x * (2.43f * x + 0.59f) + 0.14f), 0.0f, 1.0f);
        default:
            return std::min(x, 1.0f);
    }
}

int splitDividerPixel(float divider, int width) {
    if (!(divider >= 0.0f)) divider = 0.0f;  // NaN too
    divider = std::min(divider, 1.0f);
    return static_cast<int>(std::lround(double(divider) * double(std::max(width, 0))));
}

const FullscreenPass& OutputTransformPass::program(bool split, ToneCurve curve) const {
    return pass_.get({{"SPLIT_VIEW", split ? 1 : 0}, {"TONE_CURVE", static_cast<int>(curve)}});
}

Pass& OutputTransformPass::declare(FrameGraph& graph, TextureHandle linear,
                                   const std::optional<SplitView>& split, ToneCurve curve,
                                   float exposure) const {
    const FullscreenPass* pass = &program(split.has_value(), curve);
    std::optional<SplitView> view = split;
    Pass& declared =
        pass->addPass(graph, "output transform", [pass, linear, view, exposure](PassContext& ctx) {
            glProgramUniform1f(pass->program(), glsl::kOutputExposureLocation, exposure);
            GLuint after = ctx.native(linear);
            if (view) {
                // The first pixel column that shows `linear`.
                glProgramUniform1i(pass->program(), glsl::kOutputDividerLocation,
                                   splitDividerPixel(view->divider, ctx.targetSize().width));
                pass->draw({after, ctx.native(view->before)});
            } else {
                pass->draw({after});
            }
        });
    declared.read(linear);
    if (view) declared.read(view->before);
    declared.writeColor(graph.output()).setTaps(1);  // one texel, either side
    return declared;
}

}  // namespace fx
