// Lesson 05: radial blur (the Shader effects chapter, §3.6, hard cases 1 to 4, Exercises 03, 04).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <imgui.h>

#include "app/lesson.hpp"
#include "app/point_drag.hpp"
#include "app/runner.hpp"
#include "base/log.hpp"
#include "effects/post/output_transform_pass.hpp"
#include "effects/post/radial_blur.hpp"
#include "effects/scene/hdr_scene_pass.hpp"
#include "effects/scene/scene_meshes.hpp"
#include "effects/scene/scene_work.hpp"
#include "scene/scene_settings.hpp"

namespace lesson05 {

using namespace fx;

class RadialBlurLesson final : public Lesson {
public:
    std::vector<std::string> steps() const override;
    void declareParams(ParamSet& params) override;
    void update(const FrameInfo& frame) override;
    void buildFrame(FrameGraph& graph, const FrameInfo& frame) override;
    void drawPanel(const FrameInfo& frame) override;
    int benchStep() const override { return SampleCount; }
    void facts(Facts& out, const FrameInfo& frame) const override;

    enum Step { FirstVersion, ChapterStart, Guarded, SampleCount };

    // What a step blurs with: the formula, the sample count, and whether the centre sits on a pixel.
    RadialBlurParams paramsForStep(int step) const;

private:
    // Parameters, each from a postEffects.radialBlur setting: declareParams sets the setting's default
    // (the chapter's values, docs/scene-format.md).
    float centreX_{}, centreY_{};
    float length_{};
    float start_{};
    int samples_{};

    Gpu<HdrScenePass> scenePass_;
    Gpu<RadialBlur> blur_;
    Gpu<OutputTransformPass> present_;
    PassGroup blurGroup_ = groupNeeding(SceneFeature::radialBlur);
    PointDrag centreDrag_;

    // Whether both blur passes ran in the frame before `frame` (the scene asks for the blur).
    bool blurRan(const FrameInfo& frame) const;
};

namespace {

std::string numberText(float v) {
    if (std::isnan(v)) return "NaN";
    char text[32];
    std::snprintf(text, sizeof text, "%g", double(v + 0.0f));  // + 0 turns -0 into 0
    return text;
}

std::string vec2Text(glm::vec2 v) {
    return "(" + numberText(v.x) + ", " + numberText(v.y) + ")";
}

// The pixel whose centre is nearest the blur centre, if it is on the target.
bool centrePixel(const RadialBlurParams& params, Size2D size, glm::vec2& pixel) {
    glm::vec2 c = radialBlurCentrePixels(params, size);
    pixel = glm::vec2(std::floor(c.x) + 0.5f, std::floor(c.y) + 0.5f);
    return pixel.x > 0 && pixel.y > 0 && pixel.x < float(size.width) && pixel.y < float(size.height);
}

}  // namespace

std::vector<std::string> RadialBlurLesson::steps() const {
    return {
        "Zoom blur, first version",
        "A sharp centre: the chapter's formula (deliberate bug)",
        "Guarded: the centre pixel defined",
        "Sample count: what accuracy costs",
    };
}

void RadialBlurLesson::declareParams(ParamSet& params) {
    params.addSetting("centre_x", &centreX_, sceneSetting("postEffects.radialBlur.center[0]"));
    params.addSetting("centre_y", &centreY_, sceneSetting("postEffects.radialBlur.center[1]"));
    params.addSetting("length", &length_, sceneSetting("postEffects.radialBlur.length"));
    params.addSetting("start", &start_, sceneSetting("postEffects.radialBlur.start"))
        .inSteps({ChapterStart, Guarded, SampleCount});
    Param& samples = params.addSetting("samples", &samples_, sceneSetting("postEffects.radialBlur.taps"));
    samples.knob = Knob{{4, 8, 16, 32, 64}, 256, "samples"};
    samples.inSteps({SampleCount});
}

RadialBlurParams RadialBlurLesson::paramsForStep(int step) const {
    RadialBlurParams p;
    p.centre = {centreX_, centreY_};
    p.length = length_;
    p.start = start_;
    p.samples = 8;  // the chapter's count, until step 4 makes it a knob
    switch (step) {
        case FirstVersion:
            p.formula = RadialBlurFormula::firstVersion;
            break;
        case ChapterStart:
            p.formula = RadialBlurFormula::chapter;
            p.centreOnPixel = true;
            break;
        case Guarded:
            p.formula = RadialBlurFormula::guarded;
            p.centreOnPixel = true;
            break;
        default:
            p.formula = RadialBlurFormula::guarded;
            p.samples = samples_;
            break;
    }
    return p;
}

void RadialBlurLesson::update(const FrameInfo& frame) {
    // Dragging moves the centre.
    if (auto at = centreDrag_.update(frame)) {
        const SettingSpec& x = sceneSetting("postEffects.radialBlur.center[0]");
        const SettingSpec& y = sceneSetting("postEffects.radialBlur.center[1]");
        centreX_ = std::clamp(at->x, float(x.min), float(x.max));
        centreY_ = std::clamp(at->y, float(y.min), float(y.max));
    }
}

void RadialBlurLesson::buildFrame(FrameGraph& graph, const FrameInfo& frame) {
    HdrSceneTargets hdr = scenePass_->declare(graph, frame.world);
    RadialBlur::Declared blurred = [&] {
        PassGroup::Scope in(graph, blurGroup_);  // runs only when the scene asks for a radial blur
        return blur_->declare(graph, hdr.color, paramsForStep(frame.step));
    }();
    present_->declare(graph, lacks(graph, SceneFeature::radialBlur) ? hdr.color : blurred.blur.output);
}

bool RadialBlurLesson::blurRan(const FrameInfo& frame) const {
    if (!frame.previousFrame) return false;
    auto passes = blurGroup_.records(*frame.previousFrame);
    return std::all_of(passes.begin(), passes.end(), [](const PassRecord* p) { return p->executed; }) &&
           !passes.empty();
}

void RadialBlurLesson::drawPanel(const FrameInfo& frame) {
    const RadialBlurFormulaInfo& info = describe(paramsForStep(frame.step).formula);
    ImGui::TextWrapped("%s", info.formula.data());
}

void RadialBlurLesson::facts(Facts& out, const FrameInfo& frame) const {
    RadialBlurParams p = paramsForStep(frame.step);
    const RadialBlurFormulaInfo& info = describe(p.formula);
    out.add("formula", std::string(info.name));
    out.add("deliberateBug", info.deliberateBug);
    out.add("samples", std::to_string(p.samples));
    out.addAs("centrePixels", p.centreOnPixel ? "centrePixelsOnCentre" : "centrePixels",
              vec2Text(radialBlurCentrePixels(p, frame.size)));
    glm::vec2 pixel;
    if (centrePixel(p, frame.size, pixel)) {
        glm::vec2 v = radialBlurTapOffset(p, frame.size, pixel);
        out.add("offsetAtCentrePixel", vec2Text(v), {{"pixel", vec2Text(pixel)}});
        // The step that keeps the chapter's 0/0: its NaN is the lesson, so the smoke check lets these
        // textures hold it (and checks that they do).
        if (info.deliberateBug && blurRan(frame) && p.length > 0 &&
            !(std::isfinite(v.x) && std::isfinite(v.y))) {
            out.check("expectNonFiniteIn", "blur.offset, blur.result");
        }
    }
    // The farthest tap from the top-right corner, in pixels: how long the longest streak is.
    glm::vec2 corner(float(frame.size.width) - 0.5f, float(frame.size.height) - 0.5f);
    glm::vec2 reach =
        radialBlurTapOffset(p, frame.size, corner) * 7.0f * glm::vec2(frame.size.width, frame.size.height);
    out.add("streakAtCornerPixels", cat(std::hypot(reach.x, reach.y)));
    if (frame.previousFrame) out.add("blurMs", cat(blurGroup_.timeMs(*frame.previousFrame)));
}

}  // namespace lesson05

FX_LESSON(lesson05::RadialBlurLesson, "Radial blur", "scenes/05_radial_blur.json")
