#pragma once
// The frame's one output transform: linear light to the sRGB encoding the display expects, written
// into the presented output at the very end (Shader effects §3.4). Every pass before it works on
// linear values; nothing after it changes the colour. Values are clamped to [0, 1] first: there is no
// tone mapping in these lessons, so HDR values clip to white, and negative ones (a colour matrix can
// make them) to black instead of becoming NaN in the encoding curve.
//
// An optional tone curve compresses HDR light into [0, 1] before the encoding, so a lamp and the sun
// no longer both clip to the same white: Reinhard x / (1 + x), or an ACES-style filmic curve
// (Narkowicz's fit). Each works on each channel; `clip` (the default) is the chapters' picture. An
// exposure multiplies the light before the curve. ToneCurve is the scene files' type
// (scene/scene_post.hpp), so a scene's toneMap names the same curves.
//
// A split view shows two linear images through the same transform: `before` left of the divider,
// the main input right of it, with a one-pixel line on the divider.
//
//   OutputTransformPass present;
//   present.declare(graph, graded, SplitView{hdr.color, 0.5f});
#include <optional>

#include "effects/post/fullscreen_pass.hpp"
#include "effects/post/fullscreen_variants.hpp"
#include "render/frame_graph.hpp"
#include "scene/scene_post.hpp"

namespace fx {

// For people: "none (clip)", "Reinhard", "ACES-style filmic" (scene files spell them clip, reinhard,
// filmic: scene/scene_enums.hpp).
const char* toString(ToneCurve curve);
// The curve on one linear channel value (>= 0), as the shader computes it: for tests and panels.
float applyToneCurve(ToneCurve curve, float linear);

struct SplitView {
    TextureHandle before;  // shown left of the divider
    float divider = 0.5f;  // where the divider is, as a fraction of the output's width (clamped to [0, 1])
};

// The divider's x in framebuffer pixels for an output `width` wide: the first column that shows the
// main input. A fraction outside [0, 1] is clamped (0: all after, 1: all before).
int splitDividerPixel(float divider, int width);

class OutputTransformPass {
public:
    // Declares "output transform": its program (one per split view and tone curve) builds when a frame
    // first asks for it, and a pass whose program did not build is switched off with its error. Reads
    // `linear` (and split->before), writes the graph's output.
    Pass& declare(FrameGraph& graph, TextureHandle linear,
                  const std::optional<SplitView>& split = std::nullopt, ToneCurve curve = ToneCurve::clip,
                  float exposure = 1.0f) const;

private:
    const FullscreenPass& program(bool split, ToneCurve curve) const;
    FullscreenVariants pass_{"effects/post/output_transform.frag", "output transform"};
};

}  // namespace fx
