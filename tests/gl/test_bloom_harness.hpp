#pragma once
// Runs a bloom chain and its composite on a synthetic input through the frame graph on GL, as lesson 06
// does, and reads the floats back (tests/gl/test_bloom*.cpp).
#include <cmath>
#include <functional>

#include "effects/bloom/bloom_chain.hpp"
#include "effects/bloom/bloom_composite.hpp"
#include "effects/bloom/bloom_reference.hpp"
#include "gl_test.hpp"
#include "test_fullscreen_harness.hpp"

namespace fx::test {

struct BloomEffects {
    BloomChain chain;
    BloomComposite composite;
    BloomReference reference;
};

// What the texture `which` holds after the chain and composite ran: "result" is bloom.result, "glow"
// the top of the accumulated chain. `scale` is the composite's.
inline FloatImage runBloom(EffectRunner& runner, const BloomEffects& fx, const FloatImage& input,
                           TextureFormat inputFormat, const BloomChainSettings& settings, float scale,
                           const char* which = "result", int* levelsMade = nullptr) {
    return runner.run(input, inputFormat, [&](FrameGraph& g, TextureHandle in) {
        BloomChain::Declared d = fx.chain.declare(g, in, settings);
        if (levelsMade) *levelsMade = int(d.levels.size());
        if (d.empty()) return in;
        if (std::string(which) == "glow") return d.glow();
        return fx.composite.declare(g, in, d.glow(), {settings.filters, settings.upOffset, scale}).output;
    });
}

// What one texture of the chain holds after the chain ran: `pick` chooses it from what the chain
// declared (bloom.down[0] is the bright pass's output, for instance). The composite is not declared.
inline FloatImage runChain(EffectRunner& runner, const BloomEffects& fx, const FloatImage& input,
                           TextureFormat inputFormat, const BloomChainSettings& settings,
                           const std::function<TextureHandle(const BloomChain::Declared&)>& pick) {
    return runner.run(input, inputFormat, [&](FrameGraph& g, TextureHandle in) {
        BloomChain::Declared d = fx.chain.declare(g, in, settings);
        return d.empty() ? in : pick(d);
    });
}

// The reference glow composited, for a chain of `settings` and the composite weight `levelWeight`.
inline FloatImage runReference(EffectRunner& runner, const BloomEffects& fx, const FloatImage& input,
                               const BloomChainSettings& settings, Size2D size, float levelWeight) {
    return runner.run(input, TextureFormat::RGBA32F, [&](FrameGraph& g, TextureHandle in) {
        BloomReferenceSettings r{settings.threshold, settings.knee, {}, levelWeight};
        for (const BloomLevel& l : bloomLevels(size, 2, settings.levels))
            r.sigmas.push_back(bloomLevelSigma(l.index, settings.downOffset, settings.upOffset));
        BloomReference::Declared d = fx.reference.declare(g, in, r);
        if (d.empty()) return in;
        return fx.composite.declare(g, in, d.glow, {std::nullopt, 0.0f, 1.0f}).output;
    });
}

// A grey image of value v everywhere (alpha 1).
inline FloatImage uniformGrey(int width, int height, float v) {
    return makeImage(width, height, [v](int, int) { return std::array<float, 4>{v, v, v, 1.0f}; });
}

// The step-5 chain of lesson 06 without the soft knee (so the chapters' invariant applies).
inline BloomChainSettings beyondChapters(int levels = 6) {
    BloomChainSettings s = bloomChapterChain(1.0f, levels);
    s.karisAverage = true;
    return s;
}

}  // namespace fx::test
