#pragma once
// What a bloom chain is made of: which chapter's filters, the threshold, the level count, the tap
// offsets, the storage format, and the extras beyond the chapters. The two chapters' chains are two
// settings of one effect (effects/bloom/bloom_chain.hpp), because they have the same shape: a bright pass
// into the first level, downsamples to the smallest, upsamples that add each level back on the way
// up, and a composite that adds the glow to the scene.
//
//   Shader effects §3.7     bright pass to 1/4 size, E() on each of 4 taps at +-1 texel, times the
//                           intensity; 5-tap downsample (centre x4 + 4 diagonals) / 8; 9-tap
//                           upsample (centre x3, diagonals x2, axial at 2 texels x1) / 15;
//                           composite: scene + (1/N) Up(level 0).
//   Bloom §1.5-1.8          bright pass to 1/2 size, 4 diagonal taps at +-0.75 texel averaged,
//                           then the ratio; the same 4 taps down; upsample with 4 axial taps at
//                           2 x 0.5 texel (x1) and 4 diagonal at 0.5 texel (x2), / 12; composite:
//                           scene + bloomScale Up(level 0), with bloomScale a shader uniform.
#include "base/texture_format.hpp"

namespace fx {

enum class BloomFilters {
    shaderEffects,  // the Shader effects chapter, §3.7
    bloomChapter,   // the Bloom chapter, §1.5-1.8
};

// Every texel a bloom pass writes is finite and in [0, kBloomMaxValue]: below a half float's 65504
// and below R11F_G11F_B10F's 64512, so no format the chain can use turns it into infinity.
inline constexpr float kBloomMaxValue = 60000.0f;
// The bright pass keeps at most this much per texel. Eight levels summed with the non-exact halvings
// of odd sizes (about 1.1x) and a composite scale of 4 stay below kBloomMaxValue: an input that is
// finite alone cannot overflow once the levels are added up (Bloom chapter, hard case 2).
inline constexpr float kBloomMaxBright = 1024.0f;

struct BloomChainSettings {
    BloomFilters filters = BloomFilters::bloomChapter;
    int levels = 6;             // requested; a small output gets fewer (effects/bloom/bloom_levels.hpp)
    float threshold = 1.0f;     // brightness (the largest channel) where blooming starts
    float knee = 0.0f;          // soft knee, as a fraction of the threshold; 0 is the chapters' hard cut
    float extractScale = 1.0f;  // multiplies the bright pass (Shader effects' intensity)
    float downOffset = 0.75f;   // tap offsets in source texels (Shader effects: 1 and 1)
    float upOffset = 0.5f;
    bool karisAverage = false;  // weight the bright pass's taps by 1 / (1 + luma): fewer fireflies
    // The composite's blur done at half size: "bloom up 0" filters its own level too and widens its
    // upsample, and the composite reads the glow with one bilinear tap (BloomCompositeSettings::filters
    // empty) instead of eight taps at every full-size pixel.
    bool wideTop = false;
    TextureFormat format = TextureFormat::RGBA16F;  // of every level
};

// The chapters' own chains: the Shader effects chapter's (quarter size, its intensity on the bright
// pass) and the Bloom chapter's (half size, the binomial offsets).
BloomChainSettings shaderEffectsChain(float threshold = 1.0f, float intensity = 2.0f, int levels = 6);
BloomChainSettings bloomChapterChain(float threshold = 1.0f, int levels = 6);

// The first level's divisor of the output: 4 for the Shader effects chapter, 2 for the Bloom chapter.
int firstLevelDivisor(BloomFilters filters);

}  // namespace fx
