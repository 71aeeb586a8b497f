// Lesson 06: bloom, with the whole chain live (Shader effects §3.7 and the Bloom chapter,
// docs/chapters.md). Float targets first, then the two chapters' chains, then what the chapters leave
// out (Karis average, soft knee, level-independent energy, tone curves).
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include <imgui.h>

#include "app/lesson.hpp"
#include "app/runner.hpp"
#include "base/log.hpp"
#include "effects/bloom/bloom_chain.hpp"
#include "effects/bloom/bloom_composite.hpp"
#include "effects/bloom/bloom_flicker.hpp"
#include "effects/bloom/bloom_reference.hpp"
#include "effects/post/output_transform_pass.hpp"
#include "effects/scene/hdr_scene_pass.hpp"
#include "effects/scene/scene_meshes.hpp"
#include "effects/scene/scene_work.hpp"
#include "scene/scene_enums.hpp"
#include "scene/scene_settings.hpp"
#include "whole_frame.hpp"

namespace lesson06 {

using namespace fx;

namespace {

// The chain's storage formats, as the `format` parameter names them. RGBA8 is there to show what
// clipping costs: every level holds at most 1.
std::vector<TableChoice<TextureFormat>::Option> chainFormats() {
    std::vector<TableChoice<TextureFormat>::Option> options;
    for (TextureFormat format : {TextureFormat::RGBA16F, TextureFormat::R11F_G11F_B10F,
                                 TextureFormat::RGBA32F, TextureFormat::RGBA8})
        options.push_back({std::string(toString(format)), format});
    return options;
}

// Step 5's ways to end the chain (the `finish` parameter), cheapest last: where the composite's blur
// happens, and whether the composite and the output transform are one pass.
struct ChainEnd {
    bool wideTop;  // the blur done at half size (BloomChainSettings::wideTop)
    bool fused;    // the composite and the output transform in one pass
};
const std::vector<TableChoice<ChainEnd>::Option> kChainEnds = {{"full-taps", {false, false}},
                                                               {"half-wide", {true, false}},
                                                               {"full-taps-fused", {false, true}},
                                                               {"half-wide-fused", {true, true}}};

// Step 6's colour matrices (the `frame_matrix` parameter).
const std::vector<TableChoice<ColourTransform>::Option> kFrameMatrices = {
    {"identity", ColourTransform::identity()},
    {"grayscale", ColourTransform::grayscale()},
    {"sepia", ColourTransform::sepia()}};

}  // namespace

class BloomLesson final : public Lesson {
public:
    std::vector<std::string> steps() const override;
    void declareParams(ParamSet& params) override;
    void buildFrame(FrameGraph& graph, const FrameInfo& frame) override;
    void drawPanel(const FrameInfo& frame) override;
    int benchStep() const override { return Beyond; }
    std::string benchTexture() const override { return "bloom.result"; }
    std::string benchReferenceName() const override { return "Gaussian"; }
    void setBenchReference(bool on) override { benchReference_ = on; }
    void facts(Facts& out, const FrameInfo& frame) const override;

    enum Step { EightBit, HalfFloat, ShaderEffectsChain, BloomChapterChain, Beyond, WholeFrameStep };

    // The chain a step runs (steps 1 and 2 declare step 4's, switched off, so the pass table lists it).
    BloomChainSettings chainFor(int step) const;
    // The composite's scale for a chain of `levels` levels in `step`.
    float compositeScale(int step, int levels) const;
    // What a large uniform area of grey value v comes out as in `step` (the chapters' invariant):
    // v + gain * max(v - threshold, 0), with the gain for the levels that exist at `size`.
    float uniformGain(int step, Size2D size) const;

private:
    void drawWholeFramePanel(const FrameInfo& frame) const;
    void wholeFrameFacts(Facts& out, const FrameInfo& frame) const;
    bool showsReference(int step) const { return step == Beyond && (reference_ || benchReference_); }

    // Parameters. Those from a scene setting (postEffects.bloom, postEffects.toneMap) start at the
    // setting's default, which declareParams sets; the others at the chapters' values.
    float threshold_{};
    float knee_{};
    float intensity_{};        // the Shader effects chapter's intensity; step 5's glow strength
    float bloomScale_ = 2.0f;  // the Bloom chapter's (Exercise 01: 1.0)
    int levels_{};
    float downOffset_ = 0.75f;
    float upOffset_ = 0.5f;
    TableChoice<TextureFormat> format_{chainFormats(), "RGBA16F"};
    bool karis_ = true;
    TableChoice<ChainEnd> finish_{kChainEnds, "half-wide-fused"};  // step 5's way to end the chain
    Choice<ToneCurve> toneCurve_;
    float exposure_{};
    bool reference_ = false;
    bool benchReference_ = false;
    TableChoice<EffectOrder> frameOrder_{effectOrders(),
                                         effectOrders().front().name};       // step 6: the chapter's
    TableChoice<ColourTransform> frameMatrix_{kFrameMatrices, "grayscale"};  // step 6

    Gpu<HdrScenePass> scenePass_;
    Gpu<BloomChain> chain_;
    Gpu<BloomComposite> composite_;
    Gpu<BloomReference> reference_glow_;
    Gpu<BloomFlicker> flicker_;  // the glow's frame-to-frame change (bloom.flicker)
    int flickerStep_ = -1;       // the step and Karis setting the flicker measure last compared
    bool flickerKaris_ = false;
    Gpu<OutputTransformPass> present_;
    Gpu<WholeFrame> wholeFrame_;  // step 6
    // Every bloom pass (chain, composite, flicker view, reference): its time, and the scene's say.
    PassGroup bloomGroup_ = groupNeeding(SceneFeature::bloom);
};

namespace {

std::string sizesText(const std::vector<BloomLevel>& levels) {
    std::string text;
    for (const BloomLevel& l : levels)
        text += cat(text.empty() ? "" : ", ", l.size.width, "x", l.size.height);
    return text.empty() ? "none (the output is too small for the first level)" : text;
}

// The scene's brightest emitters, brightest first, by their largest channel: "firefly 900, sun 300,
// orange sphere 8". The panel quotes the scene rather than a number written here.
std::string brightestEmitters(const Scene& scene, std::size_t count) {
    std::vector<std::pair<float, std::string>> emitters;
    for (const SceneObject& o : scene.objects) {
        glm::vec3 e = o.material.emitted();
        float brightest = std::max({e.r, e.g, e.b});
        if (brightest > 0.0f) emitters.emplace_back(brightest, o.name);
    }
    std::sort(emitters.begin(), emitters.end(),
              [](const auto& a, const auto& b) { return a.first > b.first; });
    std::string text;
    for (std::size_t i = 0; i < emitters.size() && i < count; ++i)
        text += cat(i ? ", " : "", emitters[i].second, " ", emitters[i].first);
    return text.empty() ? "none" : text;
}

}  // namespace

std::vector<std::string> BloomLesson::steps() const {
    return {
        "An 8-bit target: everything bright clips",
        "A 16-bit float target: values above 1 survive",
        "The Shader effects chapter's bloom: a quarter-size chain, averaged",
        "The Bloom chapter's chain: half size, summed, bloomScale",
        "Beyond the chapters: Karis, soft knee, energy, tone curve",
        "The Shader effects chapter's whole frame, and its order",
    };
}

void BloomLesson::declareParams(ParamSet& params) {
    // The steps with a bloom chain (steps 1 and 2 compare the scene's formats before there is one).
    const std::vector<int> chainSteps = {ShaderEffectsChain, BloomChapterChain, Beyond, WholeFrameStep};
    params.addSetting("threshold", &threshold_, sceneSetting("postEffects.bloom.threshold"))
        .inSteps(chainSteps);
    params.addSetting("knee", &knee_, sceneSetting("postEffects.bloom.knee")).inSteps({Beyond});
    params.addSetting("intensity", &intensity_, sceneSetting("postEffects.bloom.intensity"))
        .inSteps({ShaderEffectsChain, Beyond, WholeFrameStep});
    params.addFloat("bloom_scale", &bloomScale_, 0.0f, 4.0f).inSteps({BloomChapterChain});
    Param& levels = params.addSetting("levels", &levels_, sceneSetting("postEffects.bloom.levels"));
    levels.knob = Knob{{2, 3, 4, 5, 6, 7, 8}, 6, "levels"};
    levels.inSteps(chainSteps);
    params.addFloat("down_offset", &downOffset_, 0.0f, 2.0f).inSteps({BloomChapterChain, Beyond});
    params.addFloat("up_offset", &upOffset_, 0.0f, 2.0f).inSteps({BloomChapterChain, Beyond});
    Param& format = params.addChoice("format", &format_);
    // The other sweeps hold the format at the one step 5 uses (RGBA16F): the error of every row is
    // measured against the Gaussian reference, not against another format.
    format.knob = Knob{{0, 1, 2, 3}, 0, "format"};
    format.inSteps(chainSteps);
    params.addBool("karis", &karis_).inSteps({Beyond});
    Param& finish = params.addChoice("finish", &finish_);
    finish.knob = Knob{{0, 1, 2, 3}, 3, "way"};
    finish.inSteps({Beyond});
    params.addSetting("tone_map", &toneCurve_, sceneSetting("postEffects.toneMap.operator"))
        .inSteps({Beyond});
    params.addSetting("exposure", &exposure_, sceneSetting("postEffects.toneMap.exposure")).inSteps({Beyond});
    params.addBool("reference", &reference_).inSteps({Beyond});
    params.addChoice("frame_order", &frameOrder_).inSteps({WholeFrameStep});
    params.addChoice("frame_matrix", &frameMatrix_).inSteps({WholeFrameStep});
}

BloomChainSettings BloomLesson::chainFor(int step) const {
    TextureFormat format = *format_;
    if (step == ShaderEffectsChain ||
        step == WholeFrameStep) {  // the whole frame is the Shader effects chapter's
        BloomChainSettings s = shaderEffectsChain(threshold_, intensity_, levels_);
        s.format = format;
        return s;
    }
    BloomChainSettings s = bloomChapterChain(threshold_, levels_);
    s.downOffset = downOffset_;
    s.upOffset = upOffset_;
    s.format = format;
    if (step == Beyond) {
        s.knee = knee_;
        s.karisAverage = karis_;
        s.wideTop = finish_->wideTop;
    }
    return s;
}

float BloomLesson::compositeScale(int step, int levels) const {
    if (step == ShaderEffectsChain || step == WholeFrameStep) return averagedCompositeScale(levels);
    if (step == Beyond) return normalisedCompositeScale(intensity_, levels);
    return bloomScale_;
}

float BloomLesson::uniformGain(int step, Size2D size) const {
    if (step < ShaderEffectsChain) return 0.0f;
    BloomChainSettings s = chainFor(step);
    int n = int(bloomLevels(size, firstLevelDivisor(s.filters), s.levels).size());
    if (n == 0) return 0.0f;
    // Every level of a uniform bright part E holds E; the up chain adds the n levels at weight 1.
    return s.extractScale * float(n) * compositeScale(step, n);
}

void BloomLesson::buildFrame(FrameGraph& graph, const FrameInfo& frame) {
    const int step = frame.step;
    if (step == WholeFrameStep) {
        WholeFrameSettings w;
        w.order = *frameOrder_;
        w.matrix = *frameMatrix_;
        w.chain = chainFor(step);
        int n =
            int(bloomLevels(graph.outputSize(), firstLevelDivisor(w.chain.filters), w.chain.levels).size());
        w.compositeScale = compositeScale(step, std::max(n, 1));
        wholeFrame_->declare(graph, frame, w, *chain_, *composite_, *present_);
        return;
    }
    TextureFormat sceneFormat = step == EightBit ? TextureFormat::RGBA8 : TextureFormat::RGBA16F;
    HdrSceneTargets hdr = scenePass_->declare(graph, frame.world, sceneFormat);
    TextureHandle shown = hdr.color;
    ToneCurve curve = step == Beyond ? *toneCurve_ : ToneCurve::clip;
    float exposure = step == Beyond ? exposure_ : 1.0f;

    // Steps 1 and 2 come before bloom: step 4's chain is declared switched off, so the pass table
    // shows what is still to come.
    const int chainStep = step < ShaderEffectsChain ? BloomChapterChain : step;
    BloomChainSettings settings = chainFor(chainStep);
    // Every bloom pass is in bloomGroup_: without bloom in the scene the graph marks them all not
    // called for, with the scene's reason, and the picture is the scene alone.
    const bool calledFor = !lacks(graph, SceneFeature::bloom);
    const bool runs = calledFor && step >= ShaderEffectsChain;
    const std::string off = cat("disabled in step ", step + 1, ": no bloom yet");
    bool presented = false;  // the fused composite wrote the output
    {
        PassGroup::Scope in(graph, bloomGroup_);

        if (showsReference(step)) {
            // The reference: what the chain approximates, computed directly
            // (effects/bloom/bloom_reference.hpp).
            std::vector<BloomLevel> levels = bloomLevels(graph.outputSize(), 2, levels_);
            BloomReferenceSettings r{
                threshold_, knee_, {}, normalisedCompositeScale(intensity_, int(levels.size()))};
            for (const BloomLevel& l : levels)
                r.sigmas.push_back(bloomLevelSigma(l.index, downOffset_, upOffset_));
            BloomReference::Declared d = reference_glow_->declare(graph, hdr.color, r);
            if (!d.empty()) {
                DeclaredPass result =
                    composite_->declare(graph, hdr.color, d.glow, {std::nullopt, 0.0f, 1.0f});
                if (calledFor) shown = result.output;
            }
        } else {
            BloomChain::Declared d = chain_->declare(graph, hdr.color, settings);
            if (!d.empty()) {
                int n = int(d.levels.size());
                // With the blur done at half size (a chain of two levels or more) one bilinear tap
                // enlarges the glow.
                std::optional<BloomFilters> enlarge = settings.filters;
                if (settings.wideTop && n > 1) enlarge.reset();
                BloomCompositeSettings c{enlarge, settings.upOffset, compositeScale(chainStep, n)};
                if (!runs) {
                    DeclaredPass result = composite_->declare(graph, hdr.color, d.glow(), c);
                    for (Pass* p : d.passes) p->disable(off);  // a scene without bloom has said why already
                    result.pass.disable(off);
                } else if (step == Beyond && finish_->fused) {
                    // The composite and the output transform in one pass: present_ has nothing left to do.
                    composite_->declarePresented(graph, hdr.color, d.glow(), c, curve, exposure);
                    presented = true;
                } else {
                    shown = composite_->declare(graph, hdr.color, d.glow(), c).output;
                }
                if (runs) {
                    // The glow's change since last frame (a moving firefly flickers it; Karis steadies it).
                    // Another step or Karis setting is a change of chain, not flicker: start over. A
                    // diagnostic (it reads the glow back every frame): bench frames leave it out.
                    if (!frame.benchmark) {
                        bool restart = step != flickerStep_ || settings.karisAverage != flickerKaris_;
                        flickerStep_ = step;
                        flickerKaris_ = settings.karisAverage;
                        flicker_->declare(graph, d.glow(), d.levels.front().size, restart);
                    } else {
                        flickerStep_ = -1;  // the next shown frame starts the comparison over
                    }
                }
            }
        }
    }  // the present pass is no part of the bloom group
    if (!presented) present_->declare(graph, shown, std::nullopt, curve, exposure);
}

void BloomLesson::drawPanel(const FrameInfo& frame) {
    const int step = frame.step;
    if (step == WholeFrameStep) {
        drawWholeFramePanel(frame);
        return;
    }
    if (step < ShaderEffectsChain) {
        const WordArgs emitters{{"emitters", brightestEmitters(frame.world.scene(), 3)}};
        ImGui::TextWrapped("%s",
                           say(step == EightBit ? "text.rangeClipped" : "text.rangeFloat", emitters).c_str());
        return;
    }
    if (flicker_->stats().measured && !showsReference(step)) {
        ImGui::TextWrapped("%s", say(step == Beyond ? "text.flickerKaris" : "text.flicker").c_str());
    }
}

void BloomLesson::facts(Facts& out, const FrameInfo& frame) const {
    const int step = frame.step;
    if (step == WholeFrameStep) wholeFrameFacts(out, frame);
    if (step < ShaderEffectsChain) {
        out.add("sceneFormat", step == EightBit ? "RGBA8" : "RGBA16F");
        out.add("brightestEmitters", brightestEmitters(frame.world.scene(), 3));
        return;
    }
    // The emitters stay in the report: the chains' text quotes the firefly and the sun from it.
    out.check("brightestEmitters", brightestEmitters(frame.world.scene(), 3));
    BloomChainSettings s = chainFor(step);
    std::vector<BloomLevel> levels = bloomLevels(frame.size, firstLevelDivisor(s.filters), s.levels);
    out.add("chainFormat", std::string(toString(s.format)));
    out.add("levels", std::to_string(levels.size()), {{"asked", cat(s.levels)}});
    out.add("levelSizes", sizesText(levels));
    out.add("compositeScale", cat(compositeScale(step, std::max(int(levels.size()), 1))));
    out.add("uniformGain", cat(uniformGain(step, frame.size)), {{"threshold", cat(threshold_)}});
    if (step == Beyond) {
        out.add("toneCurve", toString(*toneCurve_));
        out.add("reference", showsReference(step));
        out.add("finish", finish_.name());
    }
    const BloomFlicker::Stats& f = flicker_->stats();
    if (f.measured && !showsReference(step) && step != WholeFrameStep) {
        out.add("glowChangePercent", cat(f.changePercent));
        out.add("glowChangeMaxPercent", cat(f.maxPercent), {{"frames", cat(BloomFlicker::kWindow)}});
    }
    if (frame.previousFrame && step != WholeFrameStep) {
        out.add("bloomMs", cat(bloomGroup_.timeMs(*frame.previousFrame)));
        out.add("frameMs", cat(frame.previousFrame->timedMs()));
    }
}

void BloomLesson::drawWholeFramePanel(const FrameInfo& frame) const {
    const std::vector<std::string> executed =
        frame.previousFrame ? frame.previousFrame->executedPasses() : std::vector<std::string>{};
    ImGui::TextUnformatted(say("text.wholeFrame").c_str());
    if (!ImGui::BeginTable("whole frame", 2,
                           ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingStretchProp))
        return;
    ImGui::TableSetupColumn(say("text.chapterColumn").c_str());
    ImGui::TableSetupColumn(say("text.graphColumn").c_str());
    ImGui::TableHeadersRow();
    const std::vector<ChapterFrameRow>& table = chapterFrameTable();
    std::size_t rows = std::max(table.size(), executed.size());
    for (std::size_t i = 0; i < rows; ++i) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        if (i < table.size())
            ImGui::TextWrapped("%s. %s [%s]", table[i].rows.c_str(),
                               words().textOr(cat("chapter.", i + 1), table[i].action).c_str(),
                               table[i].pass.c_str());
        ImGui::TableNextColumn();
        if (i < executed.size()) ImGui::Text("%d. %s", int(i) + 1, executed[i].c_str());
    }
    ImGui::EndTable();
}

void BloomLesson::wholeFrameFacts(Facts& out, const FrameInfo& frame) const {
    out.add("frameOrder", frameOrder_.name());
    out.add("frameMatrix", frameMatrix_.name());
    std::vector<std::string> passes;
    for (const ChapterFrameRow& row : chapterFrameTable()) passes.push_back(row.pass);
    out.check("chapterTableOrder", joinedNames(passes));
    const std::vector<std::string> executed =
        frame.previousFrame ? frame.previousFrame->executedPasses() : std::vector<std::string>{};
    out.check("executedPassOrder", joinedNames(executed));
    if (frame.previousFrame) {
        std::string why;
        bool follows = followsChapterTable(executed, &why);
        const WordArgs reason{{"why", why}};
        out.add("followsChapterTable", say(follows ? "text.yes" : "text.no", reason));
    }
}

}  // namespace lesson06

FX_LESSON(lesson06::BloomLesson, "Bloom", "scenes/06_bloom.json")
