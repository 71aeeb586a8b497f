#pragma once
// The engine's own user-interface queue (Shader effects §3.3, §3.4): the last pass of the frame,
// straight into the window, with the depth test switched off and alpha blending on. It draws a small
// translucent panel in the bottom-right corner. Lesson 03 teaches the draw order with it and lesson
// 06's whole frame ends with it. Two things hang on it:
//  - it leaves the depth test off for the next frame, which is what lesson 03's reordered shadow
//    pass inherits;
//  - it runs after the full-screen pass, so no image effect touches the interface.
#include "effects/post/fullscreen_pass.hpp"
#include "render/frame_graph.hpp"

namespace fx {

class UiQueuePass {
public:
    // Draws the panel over the graph's output (`size` is the output's size this frame).
    Pass& declare(FrameGraph& graph, Size2D size) const;

    // The panel's rectangle in window pixels: 8 px from the bottom-right corner, at most 160x32, never larger
    // than the window (0x0 on a tiny one).
    static Viewport panelRect(Size2D size);

private:
    FullscreenPass pass_{"effects/post/ui_badge.frag", "ui queue"};
};

}  // namespace fx
