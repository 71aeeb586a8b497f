#pragma once
// Lesson 06: bloom, with the whole chain live (Shader effects §3.7 and the Bloom chapter,
// docs/chapters.md). Float targets first, then the two chapters' chains, then what the chapters leave
// out (Karis average, soft knee, level-independent energy, tone curves).
#include <string>
#include <vector>

#include "app/lesson.hpp"
#include "effects/bloom/bloom_chain.hpp"
#include "effects/bloom/bloom_composite.hpp"
#include "effects/bloom/bloom_flicker.hpp"
#include "effects/bloom/bloom_reference.hpp"
#include "effects/post/output_transform_pass.hpp"
#include "effects/scene/hdr_scene_pass.hpp"
#include "effects/scene/scene_meshes.hpp"
#include "effects/scene/scene_work.hpp"
#include "whole_frame.hpp"

namespace lesson06 {

class BloomLesson final : public fx::Lesson {
public:
    fx::LessonInfo info() const override;
    std::vector<std::string> steps() const override;
    void declareParams(fx::ParamSet& params) override;
    void buildFrame(fx::FrameGraph& graph, const fx::FrameInfo& frame) override;
    void drawPanel(const fx::FrameInfo& frame) override;
    int benchStep() const override { return Beyond; }
    std::string benchTexture() const override { return "bloom.result"; }
    std::string benchReferenceName() const override { return "Gaussian"; }
    void setBenchReference(bool on) override { benchReference_ = on; }
    void facts(fx::Facts& out, const fx::FrameInfo& frame) const override;

    enum Step { EightBit, HalfFloat, Chapter000, Chapter001, Beyond, WholeFrameStep };

    // The chain a step runs (steps 1 and 2 declare step 4's, switched off, so the pass table lists it).
    fx::BloomChainSettings chainFor(int step) const;
    // The composite's scale for a chain of `levels` levels in `step`.
    float compositeScale(int step, int levels) const;
    // What a large uniform area of grey value v comes out as in `step` (the chapters' invariant):
    // v + gain * max(v - threshold, 0), with the gain for the levels that exist at `size`.
    float uniformGain(int step, fx::Size2D size) const;

private:
    void drawWholeFramePanel(const fx::FrameInfo& frame) const;
    void wholeFrameFacts(fx::Facts& out, const fx::FrameInfo& frame) const;
    bool showsReference(int step) const { return step == Beyond && (reference_ || benchReference_); }

    // Parameters (the chapters' values).
    float threshold_ = 1.0f;
    float knee_ = 0.5f;
    float intensity_ = 2.0f;   // the Shader effects chapter's intensity; step 5's glow strength
    float bloomScale_ = 2.0f;  // the Bloom chapter's (Exercise 01: 1.0)
    int levels_ = 6;
    float downOffset_ = 0.75f;
    float upOffset_ = 0.5f;
    int format_ = 0;  // index into kChainFormats
    bool karis_ = true;
    int finish_ = 3;     // step 5's way to end the chain (half-wide-fused): kFinishNames in bloom_lesson.cpp
    int toneCurve_ = 2;  // fx::ToneCurve::filmic
    float exposure_ = 1.0f;
    bool reference_ = false;
    bool benchReference_ = false;
    int frameOrder_ = 0;   // step 6: index into effectOrders(), 0 the chapter's
    int frameMatrix_ = 1;  // step 6: identity, grayscale, sepia

    fx::Gpu<fx::HdrScenePass> scenePass_;
    fx::Gpu<fx::BloomChain> chain_;
    fx::Gpu<fx::BloomComposite> composite_;
    fx::Gpu<fx::BloomReference> reference_glow_;
    fx::Gpu<fx::BloomFlicker> flicker_;  // the glow's frame-to-frame change (bloom.flicker)
    int flickerStep_ = -1;               // the step and Karis setting the flicker measure last compared
    bool flickerKaris_ = false;
    fx::Gpu<fx::OutputTransformPass> present_;
    fx::Gpu<WholeFrame> wholeFrame_;  // step 6
    // Every bloom pass (chain, composite, flicker view, reference): its time, and the scene's say.
    fx::PassGroup bloomGroup_ = fx::groupNeeding(fx::SceneFeature::bloom);
};

}  // namespace lesson06
