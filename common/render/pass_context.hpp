#pragma once
// What a pass body gets while it runs: the concrete textures behind the handles it declared.
#include "render/graph_texture.hpp"

namespace fx {

class FrameGraph;
class Pass;

class PassContext {
public:
    PassContext(const FrameGraph& graph, const Pass& pass) : graph_(graph), pass_(pass) {}

    const Pass& pass() const { return pass_; }
    const FrameGraph& graph() const { return graph_; }

    // The texture behind a handle this pass declared. A handle the pass did not declare is a bug in
    // the lesson: it is logged and an empty view (native 0) comes back, so nothing is touched.
    const TextureView& texture(TextureHandle handle) const;
    NativeTexture native(TextureHandle handle) const { return texture(handle).native; }

    // The size the pass draws at: its first colour attachment, else its depth attachment, else its
    // first storage image, else the output.
    Size2D targetSize() const;
    Size2D outputSize() const;

private:
    const FrameGraph& graph_;
    const Pass& pass_;
};

}  // namespace fx
