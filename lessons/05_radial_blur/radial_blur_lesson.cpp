#include "radial_blur_lesson.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <imgui.h>

#include "base/log.hpp"
#include "scene/scene_features.hpp"

namespace lesson05 {

using namespace fx;

namespace {

constexpr float kCentreMin = -5.0f, kCentreMax = 5.0f;

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

LessonInfo RadialBlurLesson::info() const {
    return {5, "radial-blur", "Radial blur", "scenes/05_radial_blur.json"};
}

std::vector<LessonStep> RadialBlurLesson::steps() const {
    return {
        {"Zoom blur, first version",
         "Every pixel averages 8 taps on the line toward the centre: tap i at uv + v*i (i = 0..7) with v = "
         "(centre - uv) * length, each weighted 1/8. Far from the centre the taps spread wider, so the "
         "colonnade streaks outward from the gate: a sense of speed, or a pointer to one spot. Drag the "
         "centre with the mouse; length 0 switches the blur off (Exercise 03)."},
        {"A sharp centre: the chapter's formula (deliberate bug)",
         "The start distance keeps the middle sharp: v = d * (max(|d| - start, 0) / |d|) * length, which is "
         "0 within `start` of the centre (an ellipse: distances are in texture coordinates). But the pixel "
         "whose centre is the blur centre has |d| = 0, and 0/0 is NaN. This step puts the centre on a pixel "
         "centre, as an odd-sized window does with (0.5, 0.5): blur.offset holds NaN there (the inspector's "
         "NaN highlight finds it) and the taps sample at NaN positions, which GL leaves undefined."},
        {"Guarded: the centre pixel defined",
         "Where |d| <= 1e-6 the offset is set to 0: the centre pixel stays sharp, which is the limit the "
         "formula approaches there. Same centre as step 2, and no NaN. The centre may be anywhere, even off "
         "screen (centre_x = -3): taps that leave the screen read its edge (clamp to edge)."},
        {"Sample count: what accuracy costs",
         "`samples` taps spread over the same streak as the chapter's 8 (7 v long), each weighted 1/samples, "
         "so the size and brightness of the blur stay and only its smoothness changes: few samples show "
         "steps, more cost more time. The bench and the cost panel compare 4 to 64 samples with a 256-sample "
         "reference."},
    };
}

void RadialBlurLesson::declareParams(ParamSet& params) {
    params.addFloat(
        "centre_x", &centreX_, kCentreMin, kCentreMax,
        "Blur centre, x in texture coordinates (0 left, 1 right; outside is off screen; drag it)")
        .fromScene("postEffects.radialBlur.center[0]");
    params.addFloat(
        "centre_y", &centreY_, kCentreMin, kCentreMax,
        "Blur centre, y in texture coordinates (0 bottom, 1 top; outside is off screen; drag it)")
        .fromScene("postEffects.radialBlur.center[1]");
    params.addFloat(
        "length", &length_, 0.0f, 0.2f,
        "The chapter's z: tap spacing per unit of distance to the centre (0: no blur; above 1/7 the far taps "
        "overshoot the centre)")
        .fromScene("postEffects.radialBlur.length");
    params.addFloat("start", &start_, 0.0f, 2.0f,
                    "Steps 2 to 4: distance from the centre that stays sharp (texture coordinates)")
        .fromScene("postEffects.radialBlur.start");
    Param& samples = params.addInt("samples", &samples_, 1, kRadialBlurMaxSamples,
                                   "Step 4: taps per pixel, spread over the chapter's 8-tap streak");
    samples.knob = Knob{{4, 8, 16, 32, 64}, 256, "samples"};
    samples.fromScene("postEffects.radialBlur.taps");
}

Status RadialBlurLesson::init(const Scene& scene) {
    scene_ = &scene;
    meshes_ = SceneMeshes(scene);
    scenePass_ = HdrScenePass::create();
    blur_ = RadialBlur::create();
    present_ = OutputTransformPass::create();
    SceneFeatures sceneFeatures = features(scene);
    calledFor_ = sceneFeatures.has(SceneFeature::radialBlur);
    notCalledReason_ = sceneFeatures.missingReason(SceneFeature::radialBlur);
    for (auto* p : programs()) {
        if (!p->usable()) return Error{p->error()};
    }
    return Status::success();
}

void RadialBlurLesson::shutdown() {
    *this = RadialBlurLesson();
}

std::vector<gl::ReloadableProgram*> RadialBlurLesson::programs() {
    return {scenePass_.reloadable(), blur_.blurProgram(), blur_.offsetProgram(), present_.reloadable()};
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
    // Dragging moves the centre: a press that starts on the picture (not on the overlay) and holds.
    const Pointer& p = frame.pointer;
    bool down = p.present && p.leftDown;
    if (down && !wasDown_ && !p.overUi) dragging_ = true;
    if (!down) dragging_ = false;
    wasDown_ = down;
    if (dragging_ && !frame.size.empty()) {
        centreX_ = std::clamp(p.x / float(frame.size.width), kCentreMin, kCentreMax);
        centreY_ = std::clamp(p.y / float(frame.size.height), kCentreMin, kCentreMax);
    }
}

void RadialBlurLesson::buildFrame(FrameGraph& graph, const FrameInfo& frame) {
    lastStep_ = frame.step;
    lastSize_ = frame.size;
    HdrSceneTargets hdr = scenePass_.declare(graph, *scene_, meshes_, frame.seconds);
    RadialBlur::Declared blurred = blur_.declare(graph, hdr.color, paramsForStep(frame.step));
    TextureHandle shown = blurred.blur.output;
    if (!calledFor_) {
        blurred.blur.pass.notCalledFor(notCalledReason_);
        blurred.offsets.pass.notCalledFor(notCalledReason_);
        shown = hdr.color;
    }
    present_.declare(graph, shown);
    if (frame.previousFrame) {
        if (auto* pass = frame.previousFrame->findPass("radial blur"); pass && pass->timeMs)
            blurMs_ = *pass->timeMs;
    }
}

void RadialBlurLesson::drawPanel(const FrameInfo& frame) {
    RadialBlurParams p = paramsForStep(frame.step);
    const RadialBlurFormulaInfo& info = describe(p.formula);
    ImGui::TextWrapped("formula: %s%s", info.name.data(), info.deliberateBug ? " (deliberate bug)" : "");
    ImGui::TextWrapped("%s", info.formula.data());
    glm::vec2 centre = radialBlurCentrePixels(p, frame.size);
    ImGui::Text("centre: %s in pixels%s", vec2Text(centre).c_str(),
                p.centreOnPixel ? " (on a pixel centre)" : "");
    glm::vec2 pixel;
    if (centrePixel(p, frame.size, pixel)) {
        glm::vec2 v = radialBlurTapOffset(p, frame.size, pixel);
        ImGui::Text("offset v at the pixel %s: %s", vec2Text(pixel).c_str(), vec2Text(v).c_str());
    } else {
        ImGui::TextUnformatted("the centre is off screen");
    }
    // The farthest tap from the top-right corner, in pixels: how long the longest streak is.
    glm::vec2 corner(float(frame.size.width) - 0.5f, float(frame.size.height) - 0.5f);
    glm::vec2 reach =
        radialBlurTapOffset(p, frame.size, corner) * 7.0f * glm::vec2(frame.size.width, frame.size.height);
    ImGui::Text("streak at the top-right corner: %.1f px", double(std::hypot(reach.x, reach.y)));
    ImGui::Text("samples: %d, radial blur pass: %.3f ms", p.samples, blurMs_);
    if (!calledFor_) ImGui::TextWrapped("radial blur not run: %s", notCalledReason_.c_str());
}

void RadialBlurLesson::reportFacts(std::vector<std::pair<std::string, std::string>>& facts) const {
    RadialBlurParams p = paramsForStep(lastStep_);
    const RadialBlurFormulaInfo& info = describe(p.formula);
    facts.emplace_back("formula", std::string(info.name));
    facts.emplace_back("deliberateBug", info.deliberateBug ? "true" : "false");
    facts.emplace_back("samples", std::to_string(p.samples));
    facts.emplace_back("centrePixels", vec2Text(radialBlurCentrePixels(p, lastSize_)));
    glm::vec2 pixel;
    if (centrePixel(p, lastSize_, pixel)) {
        glm::vec2 v = radialBlurTapOffset(p, lastSize_, pixel);
        facts.emplace_back("offsetAtCentrePixel", vec2Text(v));
        // The step that keeps the chapter's 0/0: its NaN is the lesson, so the smoke check lets these
        // textures hold it (and checks that they do).
        if (info.deliberateBug && calledFor_ && p.length > 0 && !(std::isfinite(v.x) && std::isfinite(v.y))) {
            facts.emplace_back("expectNonFiniteIn", "blur.offset, blur.result");
        }
    }
}

}  // namespace lesson05
