#pragma once
// One full-screen copy: a texture sampled once a pixel (shaders/common/copy.frag) and written to the
// graph's output, nothing else. The bench's unit of cost (docs/bench.md), and the last pass of a
// lesson whose picture is already what the window shows.
//
//   fx::Gpu<fx::CopyPass> present_{"present"};  // the label of its GL objects
//   present_->declare(graph, "present", shown);
#include <string>

#include "effects/post/fullscreen_pass.hpp"

namespace fx {

class CopyPass {
public:
    explicit CopyPass(std::string label);

    const gl::ReloadableProgram& reloadable() const { return copy_.reloadable(); }

    // Declares pass `name`: `source` copied to the graph's output (one tap a pixel).
    Pass& declare(FrameGraph& graph, std::string name, TextureHandle source) const;

private:
    FullscreenPass copy_;
};

}  // namespace fx
