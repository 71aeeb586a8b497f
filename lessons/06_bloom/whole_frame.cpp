#include "whole_frame.hpp"

#include <cctype>

#include "base/log.hpp"

namespace lesson06 {

using namespace fx;

const std::vector<TableChoice<EffectOrder>::Option>& effectOrders() {
    using E = FrameEffect;
    static const std::vector<TableChoice<EffectOrder>::Option> orders = {
        {"bloom, radial blur, colour matrix", {E::bloom, E::radialBlur, E::colourMatrix}},
        {"colour matrix, then bloom, radial blur", {E::colourMatrix, E::bloom, E::radialBlur}},
        {"radial blur, colour matrix, then bloom", {E::radialBlur, E::colourMatrix, E::bloom}},
        {"bloom, colour matrix, radial blur", {E::bloom, E::colourMatrix, E::radialBlur}},
        {"radial blur, bloom, colour matrix", {E::radialBlur, E::bloom, E::colourMatrix}},
        {"colour matrix, radial blur, then bloom", {E::colourMatrix, E::radialBlur, E::bloom}},
    };
    return orders;
}

const std::vector<ChapterFrameRow>& chapterFrameTable() {
    // Rows 0 and 1 (the window size, sorting by render queue) are CPU work before any pass.
    static const std::vector<ChapterFrameRow> table = {
        {"2", "fboShadow (2048², DEPTH32): statics, then skinned; depth test on, blend off", "shadow map"},
        {"3-8", "fboMain (RGBA16F + depth): clear, camera, draw state, lights, opaque and transparent queues",
         "scene"},
        {"9", "fboBloom[0]: extract + 1/4 downscale from fboMain", "bloom bright pass"},
        {"10", "fboBloom[1..5]: successive 1/2 downscales", "bloom down"},
        {"11", "fboBloom[4..0]: accumulate upward (blend ONE, ONE)", "bloom up"},
        {"12", "fboMain += 1/6 of the bloom", "bloom composite"},
        {"13", "default framebuffer: radial blur", "radial blur"},
        {"13", "... then the colour matrix", "colour matrix"},
        {"13", "... then gamma 1/2.2, the one encode", "output transform"},
        {"14", "default framebuffer: the overlay/UI queue, untouched by effects", "ui queue"},
    };
    return table;
}

namespace {

// The table row a pass belongs to, or -1. A row's pass names a pass, or the start of a numbered one.
int rowOf(const std::string& pass) {
    const std::vector<ChapterFrameRow>& table = chapterFrameTable();
    for (std::size_t i = 0; i < table.size(); ++i) {
        const std::string& p = table[i].pass;
        if (pass == p || (pass.rfind(p + " ", 0) == 0 && pass.size() > p.size() + 1 &&
                          std::isdigit(static_cast<unsigned char>(pass[p.size() + 1]))))
            return int(i);
    }
    return -1;
}

}  // namespace

bool followsChapterTable(const std::vector<std::string>& executed, std::string* why) {
    const std::vector<ChapterFrameRow>& table = chapterFrameTable();
    std::vector<bool> seen(table.size(), false);
    int last = -1;
    std::string lastPass;
    for (const std::string& pass : executed) {
        int row = rowOf(pass);
        if (row < 0) continue;
        if (row < last) {
            if (why)
                *why = cat("\"", pass, "\" (row ", table[std::size_t(row)].rows, ") ran after \"", lastPass,
                           "\" (row ", table[std::size_t(last)].rows, ")");
            return false;
        }
        seen[std::size_t(row)] = true;
        last = row;
        lastPass = pass;
    }
    for (std::size_t i = 0; i < table.size(); ++i) {
        if (!seen[i]) {
            if (why) *why = cat("no pass did row ", table[i].rows, " (", table[i].pass, ")");
            return false;
        }
    }
    return true;
}

void WholeFrame::declare(FrameGraph& graph, const FrameInfo& frame, const WholeFrameSettings& settings,
                         const BloomChain& chain, const BloomComposite& composite,
                         const OutputTransformPass& present) {
    ShadowSettings shadowSettings;
    if (const Light* sun = shadowCastingLight(frame.world.scene())) shadowSettings = sun->shadow;
    DeclaredShadowMap shadow = shadows_.declare(graph, frame.world, shadowSettings, {});
    HdrSceneTargets hdr = lit_.declare(graph, frame.world, shadow);

    // The chain reads the scene wherever its glow is added, as the chapter's high pass reads fboMain.
    BloomChain::Declared glow = chain.declare(graph, hdr.color, settings.chain);
    grading_.setTransform(settings.matrix);
    TextureHandle current = hdr.color;
    for (FrameEffect effect : settings.order) {
        switch (effect) {
            case FrameEffect::bloom:
                if (!glow.empty()) {
                    BloomCompositeSettings c{settings.chain.filters, settings.chain.upOffset,
                                             settings.compositeScale};
                    current = composite.declare(graph, current, glow.glow(), c).output;
                }
                break;
            case FrameEffect::radialBlur:
                current = blur_.declare(graph, current, settings.blur).blur.output;
                break;
            case FrameEffect::colourMatrix:
                current = grading_.declare(graph, current).output;
                break;
        }
    }
    present.declare(graph, current);  // the one encode
    ui_.declare(graph, frame.size);   // after every effect: the interface stays as it was drawn
}

}  // namespace lesson06
