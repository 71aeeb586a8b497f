#include "effects/output_transform_pass.hpp"

#include <algorithm>
#include <cmath>

namespace fx {
namespace {

constexpr GLint kDividerLocation = 0;  // shaders/effects/output_transform.frag

}  // namespace

int splitDividerPixel(float divider, int width) {
    if (!(divider >= 0.0f)) divider = 0.0f;  // NaN too
    divider = std::min(divider, 1.0f);
    return static_cast<int>(std::lround(double(divider) * double(std::max(width, 0))));
}

OutputTransformPass OutputTransformPass::create() {
    OutputTransformPass p;
    p.pass_ = FullscreenPass("effects/output_transform.frag", "output transform");
    return p;
}

Pass& OutputTransformPass::declare(FrameGraph& graph, TextureHandle linear,
                                   const std::optional<SplitView>& split) const {
    const FullscreenPass* pass = &pass_;
    std::optional<SplitView> view = split;
    Pass& declared = graph.addPass("output transform", [pass, linear, view](PassContext& ctx) {
        // -1: no split. Otherwise the first pixel column that shows `linear`.
        int divider = view ? splitDividerPixel(view->divider, ctx.targetSize().width) : -1;
        glProgramUniform1i(pass->program(), kDividerLocation, divider);
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
