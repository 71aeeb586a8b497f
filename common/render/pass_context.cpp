#include "render/pass_context.hpp"

#include <algorithm>
#include <cstdlib>

#include "base/log.hpp"
#include "render/dead_stack.hpp"
#include "render/frame_graph.hpp"

namespace fx {

const TextureView& PassContext::texture(TextureHandle handle) const {
    const auto& accesses = pass_.accesses();
    bool declared = std::any_of(accesses.begin(), accesses.end(),
                                [&](const TextureAccess& a) { return a.texture == handle; });
    if (declared) return graph_.texture(handle);
    if (handle.index == kDeadStackWord) {
        // Memory is already being misread; carrying on would only hide where.
        log::error(
            "pass '", pass_.name(),
            "' read a texture handle from a stack frame that has returned: its body captured a local of the function that declared it by reference ([&]), but bodies run later, in FrameGraph::execute. Capture handles and values by copy ([=] or [handle]).");
        std::abort();
    }
    static const TextureView kNone{};
    log::error(
        "pass '", pass_.name(), "' used ",
        graph_.owns(handle) ? cat("'", graph_.texture(handle).name, "'") : std::string("a foreign handle"),
        " without declaring it");
    return kNone;
}

Size2D PassContext::targetSize() const {
    return graph_.targetSize(pass_);
}

Size2D PassContext::outputSize() const {
    return graph_.outputSize();
}

}  // namespace fx
