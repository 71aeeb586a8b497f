#include "effects/post/copy_pass.hpp"

#include <utility>

namespace fx {

CopyPass::CopyPass(std::string label) : copy_("common/copy.frag", std::move(label)) {}

Pass& CopyPass::declare(FrameGraph& graph, std::string name, TextureHandle source) const {
    // The body runs after the frame is declared: it keeps the pass's address and the handle.
    const FullscreenPass* copy = &copy_;
    return copy_
        .addPass(graph, std::move(name),
                 [copy, source](PassContext& ctx) { copy->draw({ctx.native(source)}); })
        .read(source)
        .writeColor(graph.output())
        .setTaps(1);
}

}  // namespace fx
