#include "effects/bloom/bloom_chain.hpp"

#include <string>

#include "base/log.hpp"
#include "render_gl/program_pass.hpp"

namespace fx {

std::string bloomShaderDefines() {
    // std::to_string writes "60000.000000": a float literal in GLSL, not an int.
    return cat("#define BLOOM_MAX_VALUE ", std::to_string(kBloomMaxValue), "\n#define BLOOM_MAX_BRIGHT ",
               std::to_string(kBloomMaxBright), "\n");
}

int bloomUpsampleTaps(int filters) {
    return filters == 2 ? 1 : filters == 0 ? 9 : 8;
}

void BloomSampler::bind() const {
    glBindSampler(0, sampler_.name());
    glBindSampler(1, sampler_.name());
}

void BloomSampler::unbind() {
    // Units 0 and 1 go back to their textures' own parameters: the next pass did not ask for ours.
    glBindSampler(0, 0);
    glBindSampler(1, 0);
}

namespace {

const int kBloomChapterFilters = static_cast<int>(BloomFilters::bloomChapter);

const FullscreenPass& extractProgram(const FullscreenVariants& v, int filters, bool karis) {
    // Only the Bloom chapter's filter has a Karis average; the others build without one.
    return v.get(
        {{"BLOOM_FILTERS", filters}, {"BLOOM_KARIS", filters == kBloomChapterFilters && karis ? 1 : 0}});
}
const FullscreenPass& downProgram(const FullscreenVariants& v, int filters) {
    return v.get({{"BLOOM_FILTERS", filters}});
}
const FullscreenPass& upProgram(const FullscreenVariants& v, int filters, bool wide) {
    return v.get({{"BLOOM_FILTERS", filters}, {"BLOOM_WIDE", wide ? 1 : 0}});
}

}  // namespace

BloomChain::Declared BloomChain::declare(FrameGraph& graph, TextureHandle input,
                                         const BloomChainSettings& settings) const {
    Declared d;
    d.settings = settings;
    d.levels = bloomLevels(graph.outputSize(), firstLevelDivisor(settings.filters), settings.levels);
    if (d.levels.empty()) return d;
    const int filters = static_cast<int>(settings.filters);
    const BloomSampler* sampler = &sampler_;
    auto level = [&](const char* chain, const BloomLevel& l) {
        return graph.declareTexture(cat("bloom.", chain, "[", l.index, "]"),
                                    {TextureSize::outputFraction(1, l.divisor), settings.format, 1});
    };

    // The bright pass: the scene's bright part, shrunk into level 0.
    const FullscreenPass* extract = &extractProgram(extract_, filters, settings.karisAverage);
    d.down.push_back(level("down", d.levels[0]));
    Pass& bright = extract->addPass(graph, "bloom bright pass", [=](PassContext& ctx) {
        GLuint p = extract->program();
        glProgramUniform1f(p, glsl::kBloomThresholdLocation, settings.threshold);
        glProgramUniform1f(p, glsl::kBloomKneeLocation, settings.knee);
        glProgramUniform1f(p, glsl::kBloomScaleLocation, settings.extractScale);
        glProgramUniform1f(p, glsl::kBloomOffsetLocation, settings.downOffset);
        sampler->bind();
        extract->draw({ctx.native(input)});
        BloomSampler::unbind();
    });
    bright.read(input).writeColor(d.down[0]).setTaps(4);
    d.passes.push_back(&bright);

    // Down the chain: each level from the one above it, with blending off, so the level is overwritten.
    const FullscreenPass* down = &downProgram(down_, filters);
    for (std::size_t k = 1; k < d.levels.size(); ++k) {
        TextureHandle from = d.down[k - 1];
        d.down.push_back(level("down", d.levels[k]));
        Pass& pass = down->addPass(graph, cat("bloom down ", k), [=](PassContext& ctx) {
            GLuint p = down->program();
            glProgramUniform1f(p, glsl::kBloomOffsetLocation, settings.downOffset);
            sampler->bind();
            down->draw({ctx.native(from)});
            BloomSampler::unbind();
        });
        pass.read(from).writeColor(d.down[k]).setTaps(filters == 0 ? 5 : 4);
        d.passes.push_back(&pass);
    }

    // Up the chain, smallest first: level k gets itself plus the enlarged sum of everything below it.
    std::size_t n = d.levels.size();
    d.up.resize(n > 1 ? n - 1 : 0);
    for (std::size_t k = n - 1; k-- > 0;) {
        TextureHandle below = k + 2 < n ? d.up[k + 1] : d.down[k + 1];
        TextureHandle base = d.down[k];
        d.up[k] = level("up", d.levels[k]);
        const bool wide = k == 0 && settings.wideTop;
        const FullscreenPass* up = &upProgram(up_, filters, wide);
        Pass& pass = up->addPass(graph, cat("bloom up ", k), [=](PassContext& ctx) {
            GLuint p = up->program();
            glProgramUniform1f(p, glsl::kBloomOffsetLocation, settings.upOffset);
            glProgramUniform1f(p, glsl::kBloomUpScaleLocation,
                               1.0f);  // the chapters add every level at weight 1
            sampler->bind();
            up->draw({ctx.native(base), ctx.native(below)});
            BloomSampler::unbind();
        });
        pass.read(base).read(below).writeColor(d.up[k]);
        pass.setTaps(bloomUpsampleTaps(filters) + (wide ? 4 : 1));  // the level below, then its own level
        d.passes.push_back(&pass);
    }
    // A level that is not made leaves the rest of the chain without its input.
    runTogether(d.passes);
    return d;
}

}  // namespace fx
