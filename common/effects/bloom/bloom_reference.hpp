#pragma once
// The reference glow the bench measures the chain against: what the chain approximates, computed
// directly. The same bright part (threshold and knee, one texel at a time, full resolution), blurred
// by one Gaussian per chain level with the width that level's light gets in the chain
// (effects/bloom/bloom_levels.hpp: bloomLevelSigma), each separable and exact (every tap read, 32-bit
// float, weights to 3 sigma), summed with the composite's weight per level. Kawase's "multiple
// Gaussian filter" is this sum; the chain gets close with a handful of bilinear taps per level.
//   "bloom reference bright"   input -> bloom.reference.bright (RGBA32F, full size)
//   "bloom reference x k"      bright -> bloom.reference.blur_x[k]
//   "bloom reference y k"      blur_x[k] -> bloom.reference (added up, RGBA32F)
// It costs hundreds of taps per pixel: it runs only when the lesson asks for the reference (the
// bench's reference frame, or the lesson's `reference` switch).
#include <string>
#include <vector>

#include "effects/bloom/bloom_chain.hpp"
#include "effects/post/fullscreen_pass.hpp"
#include "effects/post/fullscreen_variants.hpp"
#include "render/frame_graph.hpp"

namespace fx {

struct BloomReferenceSettings {
    float threshold = 1.0f;
    float knee = 0.0f;
    std::vector<double> sigmas;  // one Gaussian per level, in output pixels
    float levelWeight = 1.0f;    // each level's glow is added with this weight
};

class BloomReference {
public:
    struct Declared {
        TextureHandle bright;
        TextureHandle glow;  // bloom.reference: the summed glow, full size (invalid without levels)
        std::vector<Pass*> passes;
        bool empty() const { return passes.size() <= 1; }
    };
    Declared declare(FrameGraph& graph, TextureHandle input, const BloomReferenceSettings& settings) const;

private:
    // One texel of the same size (filter 2), no Karis average: the bright part exactly, per pixel.
    FullscreenPass extract_{"effects/bloom/extract.frag", "bloom reference bright pass",
                            bloomShaderDefines() + shaderDefines({{"BLOOM_FILTERS", 2}, {"BLOOM_KARIS", 0}})};
    FullscreenPass gaussian_{"effects/bloom/gaussian.frag", "bloom reference Gaussian"};
};

}  // namespace fx
