#pragma once
// The last bloom pass: the glow added onto the scene, enlarged to full size with the chain's upsample
// filter (the chapters reuse the upsample shader for it), into bloom.result (RGBA16F, the output's
// size). The scale is a shader uniform, not the blend constant: GL may clamp a blend constant to
// [0, 1], which would silently turn the Bloom chapter's bloomScale of 2 into 1 (its hard case 14).
//   Shader effects chapter: scale 1/N (N levels, each adding the bright part once)
//   Bloom chapter: scale bloomScale (2; the exercise asks for 1)
//   beyond:   scale intensity/N, so the glow's energy does not grow with the level count
//
//   BloomComposite composite;
//   DeclaredPass result = composite.declare(graph, hdr.color, chain.glow(), {BloomFilters::bloomChapter,
//   0.5f, 2.0f});
#include <optional>

#include "scene/scene_post.hpp"

#include "effects/bloom/bloom_chain.hpp"
#include "effects/bloom/bloom_settings.hpp"
#include "effects/post/fullscreen_pass.hpp"
#include "render/frame_graph.hpp"

namespace fx {

struct BloomCompositeSettings {
    // The upsample filter that enlarges the glow; nothing: the glow is already the output's size.
    std::optional<BloomFilters> filters = BloomFilters::bloomChapter;
    float upOffset = 0.5f;  // texels of the glow
    float scale = 1.0f;
};

// How much a composite scales the glow of a chain of `levels` levels: 1/N averages the levels (the
// Shader effects chapter's); intensity/N keeps a uniform area's gain for any level count (lesson 06's
// step 5). The Bloom chapter's is its bloomScale, whatever N.
float averagedCompositeScale(int levels);                     // 1/N
float normalisedCompositeScale(float intensity, int levels);  // intensity/N

class BloomComposite {
public:
    // Each filter's program builds when a frame first asks for it.
    // "bloom composite": scene + scale * Up(glow) -> bloom.result.
    DeclaredPass declare(FrameGraph& graph, TextureHandle scene, TextureHandle glow,
                         const BloomCompositeSettings& settings) const;

    // "bloom composite + output transform": the same sum, through the output transform
    // (effects/post/output_transform_pass.hpp: tone curve, exposure, sRGB encoding) straight into the
    // graph's output, with no bloom.result in between. One pass instead of two: bloom.result is
    // neither written nor read back at full size.
    Pass& declarePresented(FrameGraph& graph, TextureHandle scene, TextureHandle glow,
                           const BloomCompositeSettings& settings, ToneCurve curve, float exposure) const;

private:
    FullscreenVariants pass_{"effects/bloom/upsample.frag", "bloom composite", bloomShaderDefines()};
    FullscreenVariants presented_{"effects/bloom/composite_present.frag",
                                  "bloom composite + output transform", bloomShaderDefines()};
    BloomSampler sampler_;
};

}  // namespace fx
