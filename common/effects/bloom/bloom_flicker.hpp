#pragma once
// How much the glow changes from one frame to the next (lesson 06: fireflies). The effect keeps last
// frame's glow (bloom.up[0]) in a texture of its own, imported into the graph, and declares
//   "bloom flicker"   glow + bloom.history.previous -> bloom.flicker, bloom.history
// bloom.flicker holds |this frame's glow - last frame's| per texel (for the inspector); bloom.history
// is this frame's glow, read as "previous" next frame (two imported textures, swapped every frame, as
// docs/frame-graph.md says). The pass writes an imported texture, so it always runs: one half-size
// draw. After it, the history's mips are generated and its 1x1 level (the glow's mean) is read back:
// one texel per frame, the glow's energy, from which the frame-to-frame change in per cent follows.
//
//   BloomFlicker flicker;
//   flicker.declare(graph, chain.glow(), chain.levels[0].size, stepChanged);
//   ImGui::Text("%.2f %%", flicker.stats().changePercent);
#include <array>
#include <string>

#include "effects/post/fullscreen_pass.hpp"
#include "gl/texture.hpp"
#include "render/frame_graph.hpp"

namespace fx {

class BloomFlicker {
public:
    // `glow` is this frame's glow, `size` its size. `restart`: last frame's glow is no measure for this
    // one (another step, another chain), so this frame counts as a first frame.
    DeclaredPass declare(FrameGraph& graph, TextureHandle glow, Size2D size, bool restart);

    static constexpr int kWindow = 30;  // frames the mean and the largest change cover
    struct Stats {
        bool measured = false;     // at least one change measured since the last restart
        double meanGlow = 0;       // this frame's glow, mean luma per texel
        double changePercent = 0;  // |E - E_prev| / max(E, E_prev), in per cent
        double meanPercent = 0;    // over the last kWindow frames (fewer after a restart)
        double maxPercent = 0;
    };
    const Stats& stats() const { return stats_; }

private:
    void record(double energy, bool hasPrevious);

    FullscreenPass pass_{"effects/bloom/flicker.frag", "bloom flicker"};
    std::array<gl::Texture, 2> history_;
    Size2D size_{};
    int current_ = 0;     // history_[current_] holds the last glow written
    bool valid_ = false;  // ... and it is last frame's, at this size, for this chain
    bool ranLastFrame_ = false;
    double lastEnergy_ = 0;
    std::array<double, kWindow> window_{};
    int count_ = 0;
    Stats stats_;
};

}  // namespace fx
