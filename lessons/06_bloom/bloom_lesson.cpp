#include "bloom_lesson.hpp"

#include <algorithm>
#include <cstdio>

#include <imgui.h>

#include "base/log.hpp"
#include "scene/scene_enums.hpp"
#include "scene/scene_features.hpp"

namespace lesson06 {

using namespace fx;

namespace {

// The chain's storage formats, as the `format` parameter names them. RGBA8 is there to show what
// clipping costs: every level holds at most 1.
const TextureFormat kChainFormats[] = {TextureFormat::RGBA16F, TextureFormat::R11F_G11F_B10F,
                                       TextureFormat::RGBA32F, TextureFormat::RGBA8};

std::string sizesText(const std::vector<BloomLevel>& levels) {
    std::string text;
    for (const BloomLevel& l : levels)
        text += cat(text.empty() ? "" : ", ", l.size.width, "x", l.size.height);
    return text.empty() ? "none (the output is too small for the first level)" : text;
}

}  // namespace

LessonInfo BloomLesson::info() const {
    return {6, "bloom", "Bloom", "scenes/06_bloom.json"};
}

std::vector<LessonStep> BloomLesson::steps() const {
    return {
        {"An 8-bit target: everything bright clips",
         "The scene drawn into RGBA8. Every value is cut to [0, 1] when it is stored, so the lamp (about 6) "
         "and the "
         "sun (about 3000) both store 1 and look alike; nothing is left to tell a bright-pass filter which "
         "light is "
         "strong. The inspector's range on scene.color never goes above 1."},
        {"A 16-bit float target: values above 1 survive",
         "The same scene in RGBA16F (largest finite value 65504). The picture on screen is the same, because "
         "the "
         "display still clips at 1, but scene.color now holds the lamp's 6 and the sun's 3000: the "
         "inspector's "
         "auto-fit range and histogram show them. This costs twice the memory and bandwidth of RGBA8."},
        {"Seed 000's bloom: a quarter-size chain, averaged",
         "The bright pass keeps max(b - threshold, 0) / b of each colour (b: its brightest channel, so the "
         "hue "
         "stays) on 4 taps at +-1 texel and shrinks to a quarter (bloom.down[0]). Five downsamples (centre "
         "x4 plus "
         "four diagonals, / 8) make six levels, the upsamples (9 taps, / 15) add each level onto the next "
         "larger "
         "(bloom.up[*]), and the composite adds 1/N of the result to the scene. A uniform area v becomes "
         "v + intensity * max(v - 1, 0)."},
        {"Seed 001's chain: half size, summed, bloomScale",
         "The bright pass averages 4 diagonal taps at +-0.75 texel (a [1 3 3 1]/8 binomial) into a half-size "
         "level "
         "and then applies the ratio; the same taps go down, and the upsample reads 4 axial taps at 1 texel "
         "(weight 1) and 4 diagonal at 0.5 (weight 2), / 12. The levels are summed, not averaged, and the "
         "composite scales by bloomScale (2; the exercise asks for 1) through a shader uniform, not the "
         "blend "
         "constant, so nothing clamps it: a uniform area gains N * bloomScale times its bright part."},
        {"Beyond the chapters: Karis, soft knee, energy, tone curve",
         "A Karis average (1 / (1 + luma) weights) on the first downsample tames single bright texels, a "
         "soft knee "
         "fades the threshold in, the composite scales by intensity / N so the glow's energy does not grow "
         "with "
         "the level count, and a tone curve (Reinhard or ACES-style filmic) replaces clipping: the sun's "
         "glow now "
         "outshines the lamp's. `reference` shows the direct full-resolution Gaussian the bench compares "
         "against."},
    };
}

void BloomLesson::declareParams(ParamSet& params) {
    params.addFloat("threshold", &threshold_, 0.0f, 16.0f,
                    "Steps 3 to 5: brightness (the largest channel) above which light blooms")
        .fromScene("postEffects.bloom.threshold");
    params.addFloat("knee", &knee_, 0.0f, 1.0f,
                    "Step 5: soft knee as a fraction of the threshold (0: the chapters' hard cut)")
        .fromScene("postEffects.bloom.knee");
    params.addFloat(
        "intensity", &intensity_, 0.0f, 4.0f,
        "Step 3: seed 000's intensity; step 5: the glow's strength (a uniform area gains this times its "
        "bright part, for any level count)")
        .fromScene("postEffects.bloom.intensity");
    params.addFloat("bloom_scale", &bloomScale_, 0.0f, 4.0f,
                    "Step 4: seed 001's bloomScale, applied by a shader uniform (Exercise 01: 1.0)");
    Param& levels = params.addInt("levels", &levels_, 1, kBloomMaxLevels,
                                  "Steps 3 to 5: levels in the chain (fewer when the window is too small)");
    levels.knob = Knob{{2, 3, 4, 5, 6, 7, 8}, 6, "levels"};
    levels.fromScene("postEffects.bloom.levels");
    params.addFloat(
        "down_offset", &downOffset_, 0.0f, 2.0f,
        "Steps 4 and 5: bright-pass and downsample tap offset, in source texels (seed 001: 0.75)");
    params.addFloat("up_offset", &upOffset_, 0.0f, 2.0f,
                    "Steps 4 and 5: upsample tap offset, in source texels (seed 001: 0.5)");
    Param& format =
        params.addChoice("format", &format_, {"RGBA16F", "R11F_G11F_B10F", "RGBA32F", "RGBA8"},
                         "Steps 3 to 5: the chain's colour format (RGBA8 shows what clipping costs)");
    format.knob = Knob{{0, 1, 2, 3}, 2, "format"};
    params.addBool("karis", &karis_, "Step 5: Karis average on the first downsample (fewer fireflies)");
    params
        .addChoice("tone_map", &toneCurve_, enumNameList<ToneCurve>(),
                   "Step 5: the output's tone curve (clip: none, everything above 1 clips, as in the chapters)")
        .fromScene("postEffects.toneMap.operator");
    params.addFloat("exposure", &exposure_, 0.01f, 16.0f, "Step 5: multiplies the light before the tone curve")
        .fromScene("postEffects.toneMap.exposure");
    params.addBool(
        "reference", &reference_,
        "Step 5: show the reference instead of the chain: a direct full-resolution Gaussian per level "
        "(slow)");
}

Status BloomLesson::init(const Scene& scene) {
    scene_ = &scene;
    meshes_ = SceneMeshes(scene);
    scenePass_ = HdrScenePass::create();
    chain_ = BloomChain::create();
    composite_ = BloomComposite::create();
    reference_glow_ = BloomReference::create();
    flicker_ = BloomFlicker::create();
    present_ = OutputTransformPass::create();
    SceneFeatures sceneFeatures = features(scene);
    calledFor_ = sceneFeatures.has(SceneFeature::bloom);
    notCalledReason_ = sceneFeatures.missingReason(SceneFeature::bloom);
    for (auto* p : programs()) {
        if (!p->usable()) return Error{p->error()};
    }
    return Status::success();
}

void BloomLesson::shutdown() {
    *this = BloomLesson();
}

std::vector<gl::ReloadableProgram*> BloomLesson::programs() {
    std::vector<gl::ReloadableProgram*> list{scenePass_.reloadable(), composite_.reloadable(),
                                             present_.reloadable(), flicker_.reloadable()};
    for (auto* p : chain_.programs()) list.push_back(p);
    for (auto* p : reference_glow_.programs()) list.push_back(p);
    return list;
}

BloomChainSettings BloomLesson::chainFor(int step) const {
    TextureFormat format = kChainFormats[std::clamp(format_, 0, 3)];
    if (step == Chapter000) {
        BloomChainSettings s = chapter000Bloom(threshold_, intensity_, levels_);
        s.format = format;
        return s;
    }
    BloomChainSettings s = chapter001Bloom(threshold_, levels_);
    s.downOffset = downOffset_;
    s.upOffset = upOffset_;
    s.format = format;
    if (step == Beyond) {
        s.knee = knee_;
        s.karisAverage = karis_;
    }
    return s;
}

float BloomLesson::compositeScale(int step, int levels) const {
    if (step == Chapter000) return chapter000CompositeScale(levels);
    if (step == Beyond) return normalisedCompositeScale(intensity_, levels);
    return bloomScale_;
}

float BloomLesson::uniformGain(int step, Size2D size) const {
    if (step < Chapter000) return 0.0f;
    BloomChainSettings s = chainFor(step);
    int n = int(bloomLevels(size, firstLevelDivisor(s.filters), s.levels).size());
    if (n == 0) return 0.0f;
    // Every level of a uniform bright part E holds E; the up chain adds the n levels at weight 1.
    return s.extractScale * float(n) * compositeScale(step, n);
}

void BloomLesson::buildFrame(FrameGraph& graph, const FrameInfo& frame) {
    lastStep_ = frame.step;
    lastSize_ = frame.size;
    const int step = frame.step;
    TextureFormat sceneFormat = step == EightBit ? TextureFormat::RGBA8 : TextureFormat::RGBA16F;
    HdrSceneTargets hdr = scenePass_.declare(graph, *scene_, meshes_, frame.seconds, sceneFormat);
    TextureHandle shown = hdr.color;
    ToneCurve curve = step == Beyond ? static_cast<ToneCurve>(std::clamp(toneCurve_, 0, 2)) : ToneCurve::clip;
    float exposure = step == Beyond ? exposure_ : 1.0f;

    // Steps 1 and 2 come before bloom: step 4's chain is declared switched off, so the pass table
    // shows what is still to come.
    const int chainStep = step < Chapter000 ? Chapter001 : step;
    BloomChainSettings settings = chainFor(chainStep);
    std::string off;
    if (step < Chapter000) off = cat("disabled in step ", step + 1, ": no bloom yet");
    if (!calledFor_) off = notCalledReason_;

    if (showsReference(step)) {
        // The reference: what the chain approximates, computed directly (effects/bloom/bloom_reference.hpp).
        std::vector<BloomLevel> levels = bloomLevels(graph.outputSize(), 2, levels_);
        BloomReferenceSettings r{
            threshold_, knee_, {}, normalisedCompositeScale(intensity_, int(levels.size()))};
        for (const BloomLevel& l : levels)
            r.sigmas.push_back(bloomLevelSigma(l.index, downOffset_, upOffset_));
        BloomReference::Declared d = reference_glow_.declare(graph, hdr.color, r);
        if (!d.empty()) {
            DeclaredPass result = composite_.declare(graph, hdr.color, d.glow, {std::nullopt, 0.0f, 1.0f});
            if (!calledFor_) {
                for (Pass* p : d.passes) p->notCalledFor(off);
                result.pass.notCalledFor(off);
            } else {
                shown = result.output;
            }
        }
    } else {
        BloomChain::Declared d = chain_.declare(graph, hdr.color, settings);
        if (!d.empty()) {
            int n = int(d.levels.size());
            BloomCompositeSettings c{settings.filters, settings.upOffset, compositeScale(chainStep, n)};
            DeclaredPass result = composite_.declare(graph, hdr.color, d.glow(), c);
            if (!off.empty()) {
                for (Pass* p : d.passes) calledFor_ ? p->disable(off) : p->notCalledFor(off);
                calledFor_ ? result.pass.disable(off) : result.pass.notCalledFor(off);
            } else {
                shown = result.output;
                // The glow's change since last frame (a moving firefly flickers it; Karis steadies it).
                // Another step or Karis setting is a change of chain, not flicker: start over. A
                // diagnostic (it reads the glow back every frame): bench frames leave it out.
                if (!frame.benchmark) {
                    bool restart = step != flickerStep_ || settings.karisAverage != flickerKaris_;
                    flickerStep_ = step;
                    flickerKaris_ = settings.karisAverage;
                    flicker_.declare(graph, d.glow(), d.levels.front().size, restart);
                } else {
                    flickerStep_ = -1;  // the next shown frame starts the comparison over
                }
            }
        }
    }
    present_.declare(graph, shown, std::nullopt, curve, exposure);

    if (frame.previousFrame) {
        double bloom = 0, total = 0;
        for (const PassRecord& p : frame.previousFrame->passes) {
            if (!p.timeMs) continue;
            total += *p.timeMs;
            if (p.name.rfind("bloom", 0) == 0) bloom += *p.timeMs;
        }
        bloomMs_ = bloom;
        frameMs_ = total;
    }
}

void BloomLesson::drawPanel(const FrameInfo& frame) {
    const int step = frame.step;
    if (step < Chapter000) {
        ImGui::TextWrapped("scene.color: %s. Inspect it and look at the range: %s",
                           step == EightBit ? "RGBA8" : "RGBA16F",
                           step == EightBit ? "nothing above 1." : "the sun's disc holds thousands.");
        return;
    }
    BloomChainSettings s = chainFor(step);
    std::vector<BloomLevel> levels = bloomLevels(frame.size, firstLevelDivisor(s.filters), s.levels);
    int n = int(levels.size());
    ImGui::TextWrapped("chain (%s): %d of %d levels: %s", toString(s.format).data(), n, s.levels,
                       sizesText(levels).c_str());
    ImGui::Text("composite scale: %.4g", double(compositeScale(step, std::max(n, 1))));
    ImGui::TextWrapped("a uniform grey area v comes out as v + %.4g * max(v - %.3g, 0)",
                       double(uniformGain(step, frame.size)), double(threshold_));
    if (step == Beyond) {
        ImGui::Text("tone curve: %s%s", toString(static_cast<ToneCurve>(std::clamp(toneCurve_, 0, 2))),
                    showsReference(step) ? ", showing the reference Gaussian" : "");
    }
    const BloomFlicker::Stats& f = flicker_.stats();
    if (f.measured && !showsReference(step)) {
        ImGui::Text("glow change since last frame: %.2f %% (last %d frames: mean %.2f %%, max %.2f %%)",
                    f.changePercent, BloomFlicker::kWindow, f.meanPercent, f.maxPercent);
        ImGui::TextWrapped("Inspect bloom.flicker to see where: |this frame's glow - last frame's|.%s",
                           step == Beyond ? " Switch karis off to see the firefly flicker." : "");
    }
    ImGui::Text("bloom passes: %.3f ms of %.3f ms", bloomMs_, frameMs_);
    if (!calledFor_) ImGui::TextWrapped("bloom not run: %s", notCalledReason_.c_str());
}

void BloomLesson::reportFacts(std::vector<std::pair<std::string, std::string>>& facts) const {
    if (lastStep_ < Chapter000) {
        facts.emplace_back("sceneFormat", lastStep_ == EightBit ? "RGBA8" : "RGBA16F");
        return;
    }
    BloomChainSettings s = chainFor(lastStep_);
    std::vector<BloomLevel> levels = bloomLevels(lastSize_, firstLevelDivisor(s.filters), s.levels);
    facts.emplace_back("chainFormat", std::string(toString(s.format)));
    facts.emplace_back("levels", std::to_string(levels.size()));
    facts.emplace_back("levelSizes", sizesText(levels));
    facts.emplace_back("compositeScale", cat(compositeScale(lastStep_, std::max(int(levels.size()), 1))));
    facts.emplace_back("uniformGain", cat(uniformGain(lastStep_, lastSize_)));
    if (lastStep_ == Beyond) {
        facts.emplace_back("toneCurve", toString(static_cast<ToneCurve>(std::clamp(toneCurve_, 0, 2))));
        facts.emplace_back("reference", showsReference(lastStep_) ? "true" : "false");
    }
}

}  // namespace lesson06
