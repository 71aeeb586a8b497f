#include "render/pass_context.hpp"

#include <algorithm>

#include "base/log.hpp"
#include "render/frame_graph.hpp"

namespace fx {

const TextureView& PassContext::texture(TextureHandle handle) const {
    const auto& accesses = pass_.accesses();
    bool declared = std::any_of(accesses.begin(), accesses.end(),
                                [&](const TextureAccess& a) { return a.texture == handle; });
    if (declared) return graph_.texture(handle);
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
