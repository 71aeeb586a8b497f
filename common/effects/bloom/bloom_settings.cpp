#include "effects/bloom/bloom_settings.hpp"

namespace fx {

BloomChainSettings shaderEffectsChain(float threshold, float intensity, int levels) {
    BloomChainSettings s;
    s.filters = BloomFilters::shaderEffects;
    s.levels = levels;
    s.threshold = threshold;
    s.extractScale = intensity;
    s.downOffset = 1.0f;  // the 2x2 quad centres around a texel corner
    s.upOffset = 1.0f;
    return s;
}

BloomChainSettings bloomChapterChain(float threshold, int levels) {
    BloomChainSettings s;
    s.filters = BloomFilters::bloomChapter;
    s.levels = levels;
    s.threshold = threshold;
    s.downOffset = 0.75f;  // the [1 3 3 1]/8 binomial at an exact 2:1 ratio
    s.upOffset = 0.5f;
    return s;
}

int firstLevelDivisor(BloomFilters filters) {
    return filters == BloomFilters::shaderEffects ? 4 : 2;
}

}  // namespace fx
