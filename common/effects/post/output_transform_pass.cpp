#include "effects/post/output_transform_pass.hpp"

#include <algorithm>
#include <cmath>

namespace fx {
namespace {

constexpr GLint kDividerLocation = 0;  // shaders/effects/output_transform.frag
constexpr GLint kCurveLocation = 1;
constexpr GLint kExposureLocation = 2;

}  // namespace

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

OutputTransformPass OutputTransformPass::create() {
    OutputTransformPass p;
    p.pass_ = FullscreenPass("effects/post/output_transform.frag", "output transform");
    return p;
}

Pass& OutputTransformPass::declare(FrameGraph& graph, TextureHandle linear,
                                   const std::optional<SplitView>& split, ToneCurve curve,
                                   float exposure) const {
    const FullscreenPass* pass = &pass_;
    std::optional<SplitView> view = split;
    Pass& declared =
        graph.addPass("output transform", [pass, linear, view, curve, exposure](PassContext& ctx) {
            // -1: no split. Otherwise the first pixel column that shows `linear`.
            int divider = view ? splitDividerPixel(view->divider, ctx.targetSize().width) : -1;
            glProgramUniform1i(pass->program(), kDividerLocation, divider);
            glProgramUniform1i(pass->program(), kCurveLocation, static_cast<int>(curve));
            glProgramUniform1f(pass->program(), kExposureLocation, exposure);
            GLuint after = ctx.native(linear);
            pass->draw({after, view ? ctx.native(view->before) : after});
        });
    declared.read(linear);
    if (view) declared.read(view->before);
    declared.writeColor(graph.output()).setState(FullscreenPass::state());
    if (!pass_.usable()) declared.disable("the output transform program did not build: " + pass_.error());
    return declared;
}

}  // namespace fx
