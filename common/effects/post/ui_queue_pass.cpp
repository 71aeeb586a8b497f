#include "effects/post/ui_queue_pass.hpp"

#include <algorithm>

#include "effects/post/post_bindings.hpp"

namespace fx {

Viewport UiQueuePass::panelRect(Size2D size) {
    constexpr int kMargin = 8;
    Viewport rect;
    rect.width = std::clamp(size.width - 2 * kMargin, 0, 160);
    rect.height = std::clamp(size.height - 2 * kMargin, 0, 32);
    // Bottom right, where the overlay's windows are not.
    rect.x = std::max(size.width - kMargin - rect.width, 0);
    rect.y = std::min(kMargin, size.height);
    return rect;
}

Pass& UiQueuePass::declare(FrameGraph& graph, Size2D size) const {
    const FullscreenPass* pass = &pass_;
    Viewport rect = panelRect(size);
    Pass& ui = pass_.addPass(graph, "ui queue", [pass, rect](PassContext&) {
        glProgramUniform4f(pass->program(), glsl::kUiPanelLocation, float(rect.x), float(rect.y),
                           float(rect.width), float(rect.height));
        pass->draw({});
    });
    ui.modify(graph.output(), TextureUsage::ColorAttachment).setTaps(0);  // a flat panel, no texture
    // The chapter's overlay queue: depth test off, blending on. Depth writes are left as they are
    // (on): the chapter's engine never turns them off, and with the test off nothing is written.
    ui.setState({.viewport = rect,
                 .depthTest = false,
                 .blend = true,
                 .blendFunction = BlendFunction::alpha(),
                 .faceCulling = false,
                 .colorMask = ColorMask{}});
    return ui;
}

}  // namespace fx
