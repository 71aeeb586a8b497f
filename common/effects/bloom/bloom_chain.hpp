#pragma once
// The bloom chain of the Shader effects and Bloom chapters (bloom_settings.hpp says which filters): the
// bright part of the scene shrunk into the first level, each level blurred down into the next, then each
// level added back on the way up. Declared on the frame graph as
//   "bloom bright pass"     input          -> bloom.down[0]
//   "bloom down k"          bloom.down[k-1] -> bloom.down[k]          k = 1 .. N-1
//   "bloom up k"            bloom.down[k] + Up(bloom.up[k+1]) -> bloom.up[k]   k = N-2 .. 0
// (the smallest level's accumulated value is bloom.down[N-1] itself). With settings.wideTop, "bloom up 0"
// also blurs its own level and widens its upsample, so bloom.up[0] is the glow the composite used to
// blur at full size with eight taps per pixel: the composite then takes one bilinear tap of it. The chapters
// add the enlarged level onto the level in place with additive blending; keeping the sum in a texture of its
// own gives the same numbers and lets the inspector's chain strip show every level before (bloom.down[*]) and
// after (bloom.up[*]) accumulation. The graph tracks whole textures, so every level is a texture.
//
// Sizes follow the output every frame (effects/bloom/bloom_levels.hpp); a level below one texel is not made,
// and an output too small for even the first level declares nothing.
//
//   BloomChain chain;
//   BloomChain::Declared d = chain.declare(graph, hdr.color, bloomChapterChain());
//   composite.declare(graph, hdr.color, d, ...);
#include <string>
#include <vector>

#include "effects/bloom/bloom_bindings.hpp"
#include "effects/bloom/bloom_levels.hpp"
#include "effects/bloom/bloom_settings.hpp"
#include "effects/post/fullscreen_pass.hpp"
#include "effects/post/fullscreen_variants.hpp"
#include "render/frame_graph.hpp"

namespace fx {

// What the GLSL of the bloom passes gets as defines: the limits of effects/bloom/bloom_settings.hpp.
std::string bloomShaderDefines();

// Texture lookups of bloom_common.glsl's upsampleFilter for BLOOM_FILTERS `filters` (the passes' taps):
// 9 for the Shader effects chapter's tent (0), 8 for the Bloom chapter's (1), one bilinear tap (2).
int bloomUpsampleTaps(int filters);

// A sampler with GL_LINEAR and CLAMP_TO_EDGE bound to units 0 and 1 for one draw: the chapters' kernels
// rely on bilinear taps, and REPEAT would bring light from the opposite edge (Bloom, hard case 11).
// Whatever a texture's own parameters say, the bloom passes filter the same way.
class BloomSampler {
public:
    void bind() const;
    static void unbind();

private:
    gl::SamplerName sampler_ = gl::createLinearClampSampler("bloom (linear, clamp to edge)");
};

class BloomChain {
public:
    struct Declared {
        BloomChainSettings settings;
        std::vector<BloomLevel> levels;   // those that exist at this output size
        std::vector<TextureHandle> down;  // bloom.down[k]: level k before accumulation
        std::vector<TextureHandle> up;    // bloom.up[k], k < N-1: level k plus everything below it
        std::vector<Pass*> passes;
        bool empty() const { return levels.empty(); }
        // The top of the accumulated chain (bloom.up[0], or bloom.down[0] for a one-level chain).
        TextureHandle glow() const { return up.empty() ? down.front() : up.front(); }
    };
    // Declares nothing when no level fits the output. The programs for `settings` build when a frame
    // first asks for them; when one of them did not build, the whole chain is switched off with its
    // error.
    Declared declare(FrameGraph& graph, TextureHandle input, const BloomChainSettings& settings) const;

private:
    FullscreenVariants extract_{"effects/bloom/extract.frag", "bloom bright pass", bloomShaderDefines()};
    FullscreenVariants down_{"effects/bloom/downsample.frag", "bloom downsample", bloomShaderDefines()};
    FullscreenVariants up_{"effects/bloom/upsample.frag", "bloom upsample", bloomShaderDefines()};
    BloomSampler sampler_;
};

}  // namespace fx
