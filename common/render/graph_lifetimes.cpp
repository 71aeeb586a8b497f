// When each transient texture holds memory: from just before the first pass that runs and touches
// it (always its creator) to just after the last one, in execution order. Inspected and captured
// textures are held to the end of the frame, for the overlay and the capture.
#include "render/graph_compiler.hpp"

namespace fx {

void planLifetimes(const PassList& passes, const std::vector<GraphTexture>& textures, CompiledGraph& graph) {
    constexpr std::uint32_t kUnused = UINT32_MAX;
    std::vector<std::uint32_t> first(textures.size(), kUnused);
    std::vector<std::uint32_t> last(textures.size(), kUnused);
    for (std::uint32_t p : graph.executionOrder) {
        for (const auto& a : passes[p]->accesses()) {
            std::uint32_t t = a.texture.index;
            if (!textures[t].transient()) continue;
            if (first[t] == kUnused) first[t] = p;
            last[t] = p;
        }
    }
    graph.acquireBefore.assign(passes.size(), {});
    graph.releaseAfter.assign(passes.size(), {});
    graph.retained.clear();
    for (std::uint32_t t = 0; t < textures.size(); ++t) {
        if (first[t] == kUnused) continue;
        graph.acquireBefore[first[t]].push_back(t);
        if (textures[t].inspected || textures[t].captured) {
            graph.retained.push_back(t);
        } else {
            graph.releaseAfter[last[t]].push_back(t);
        }
    }
}

}  // namespace fx
