// Lesson 04: colour matrix (the Shader effects chapter, §3.4, §3.5, hard cases 5 to 8, Exercise 02).
#include <algorithm>
#include <array>
#include <cstdio>

#include <imgui.h>

#include "app/lesson.hpp"
#include "app/point_drag.hpp"
#include "app/runner.hpp"
#include "base/log.hpp"
#include "effects/post/colour_matrix.hpp"
#include "effects/post/output_transform_pass.hpp"
#include "effects/scene/hdr_scene_pass.hpp"
#include "effects/scene/scene_meshes.hpp"
#include "effects/scene/scene_work.hpp"
#include "scene/scene_settings.hpp"

namespace lesson04 {

using namespace fx;

namespace {

// The `channel_order` choices: output (r, g, b) takes these input channels.
const std::vector<TableChoice<std::array<int, 3>>::Option> kChannelOrders = {
    {"rgb", {0, 1, 2}}, {"rbg", {0, 2, 1}}, {"grb", {1, 0, 2}},
    {"gbr", {1, 2, 0}}, {"brg", {2, 0, 1}}, {"bgr", {2, 1, 0}}};

}  // namespace

class ColourMatrixLesson final : public Lesson {
public:
    std::vector<std::string> steps() const override;
    void declareParams(ParamSet& params) override;
    void update(const FrameInfo& frame) override;
    void buildFrame(FrameGraph& graph, const FrameInfo& frame) override;
    void drawPanel(const FrameInfo& frame) override;
    void facts(Facts& out, const FrameInfo& frame) const override;

    enum Step { Identity, Grayscale, Sepia, Affine };
    // The presets of step 4 (the `preset` parameter), in the order of its choices.
    enum Preset {
        None,
        GrayscalePreset,
        SepiaPreset,
        Saturation,
        HueRotation,
        ChannelSwap,
        BrightnessContrast,
        Invert,
        Invert3x3,
        Custom,
    };

private:
    // Parameters.
    int preset_ = Invert;
    float amount_{};  // from postEffects.colorMatrix.amount: declareParams sets the setting's default
    float saturation_ = 1.8f;
    float hueDegrees_ = 120.0f;
    TableChoice<std::array<int, 3>> channelOrder_{kChannelOrders, "gbr"};
    float brightness_ = 0.1f;
    float contrast_ = 1.4f;
    bool splitView_ = true;
    float divider_ = 0.72f;  // right of the blue cylinder: every object but the capsule is processed

    Gpu<HdrScenePass> scenePass_;
    Gpu<ColourMatrixPass> grading_;
    Gpu<OutputTransformPass> present_;
    ColourTransform custom_;  // the matrix edited in the overlay (preset "custom")
    PassGroup gradingGroup_ = groupNeeding(SceneFeature::colorMatrix);
    PointDrag dividerDrag_;

    // The transform the step (and, in step 4, the preset) selects, before `amount`.
    ColourTransform selected(int step) const;
    ColourTransform presetTransform(int preset) const;
};

namespace {

std::string vec3Text(const glm::vec3& v) {
    char text[96];
    std::snprintf(text, sizeof text, "(%.4f, %.4f, %.4f)", double(v.x), double(v.y), double(v.z));
    return text;
}

// The transform as text, one equation per output channel: "r' = 0.2126 r + 0.7152 g + 0.0722 b + 0".
std::string equations(const ColourTransform& t) {
    std::string out;
    const char* names[] = {"r'", "g'", "b'"};
    for (int c = 0; c < 3; ++c) {
        glm::vec3 row = t.row(c);
        char line[160];
        std::snprintf(line, sizeof line, "%s = %.4f r + %.4f g + %.4f b + %.4f", names[c], double(row.x),
                      double(row.y), double(row.z), double(t.offset[c]));
        out += (c ? "; " : "") + std::string(line);
    }
    return out;
}

}  // namespace

std::vector<std::string> ColourMatrixLesson::steps() const {
    return {
        "Render into a float target; one output transform",
        "Grayscale: Rec.709 luma",
        "Sepia: the chapter's matrix",
        "Beyond a 3x3: an affine transform",
    };
}

void ColourMatrixLesson::declareParams(ParamSet& params) {
    // The scene's colorMatrix names the starting preset (identity, grayscale, sepia or invert) and amount.
    // Step 4's choices are step 4's alone: the panel of steps 1 to 3 shows the chapter's matrix, not a
    // preset those steps do not use.
    const std::vector<int> affine{Affine};
    params
        .addChoice("preset", &preset_,
                   {"identity", "grayscale", "sepia", "saturation", "hue_rotation", "channel_swap",
                    "brightness_contrast", "invert", "invert_3x3", "custom"})
        .fromScene("postEffects.colorMatrix.preset")
        .inSteps(affine);
    params.addSetting("amount", &amount_, sceneSetting("postEffects.colorMatrix.amount"));
    params.addFloat("saturation", &saturation_, -1.0f, 3.0f).inSteps(affine);
    params.addFloat("hue_degrees", &hueDegrees_, -180.0f, 180.0f).inSteps(affine);
    params.addChoice("channel_order", &channelOrder_).inSteps(affine);
    params.addFloat("brightness", &brightness_, -1.0f, 1.0f).inSteps(affine);
    params.addFloat("contrast", &contrast_, 0.0f, 4.0f).inSteps(affine);
    params.addBool("split_view", &splitView_);
    params.addFloat("divider", &divider_, 0.0f, 1.0f);
}

ColourTransform ColourMatrixLesson::presetTransform(int preset) const {
    switch (preset) {
        case GrayscalePreset:
            return ColourTransform::grayscale();
        case SepiaPreset:
            return ColourTransform::sepia();
        case Saturation:
            return ColourTransform::saturation(saturation_);
        case HueRotation:
            return ColourTransform::hueRotation(hueDegrees_);
        case ChannelSwap:
            return ColourTransform::channelSwap(*channelOrder_);
        case BrightnessContrast:
            return ColourTransform::brightnessContrast(brightness_, contrast_);
        case Invert:
            return ColourTransform::invert();
        case Invert3x3:
            return ColourTransform::negate();
        case Custom:
            return custom_;
        default:
            return ColourTransform::identity();
    }
}

ColourTransform ColourMatrixLesson::selected(int step) const {
    switch (step) {
        case Identity:
            return ColourTransform::identity();
        case Grayscale:
            return ColourTransform::grayscale();
        case Sepia:
            return ColourTransform::sepia();
        default:
            return presetTransform(preset_);
    }
}

void ColourMatrixLesson::update(const FrameInfo& frame) {
    // Dragging moves the divider.
    if (auto at = dividerDrag_.update(frame); at && splitView_) divider_ = std::clamp(at->x, 0.0f, 1.0f);
}

void ColourMatrixLesson::buildFrame(FrameGraph& graph, const FrameInfo& frame) {
    // Exercise 02: the lesson chooses a transform value and hands it to the one setter.
    grading_->setTransform(blendFromIdentity(selected(frame.step), amount_));

    HdrSceneTargets hdr = scenePass_->declare(graph, frame.world);
    DeclaredPass graded = [&] {
        PassGroup::Scope in(graph, gradingGroup_);  // runs only when the scene asks for a colour matrix
        return grading_->declare(graph, hdr.color);
    }();
    const bool calledFor = !lacks(graph, SceneFeature::colorMatrix);
    TextureHandle shown = calledFor ? graded.output : hdr.color;
    // The split view is for people; a bench frame measures the effect alone.
    // The matrix's picture goes left of the divider, where the scene's red box, green sphere and blue
    // cylinder stand (the objects the steps' text talks about); the untouched frame is on the right.
    if (splitView_ && calledFor && !frame.benchmark) {
        present_->declare(graph, hdr.color, SplitView{graded.output, divider_});
        return;
    }
    present_->declare(graph, shown);
}

void ColourMatrixLesson::drawPanel(const FrameInfo& frame) {
    ColourTransform t = selected(frame.step);
    bool editable = frame.step == Affine;
    bool changed = false;
    if (ImGui::BeginTable("matrix", 4, ImGuiTableFlags_SizingStretchSame)) {
        const char* rows[] = {"r'", "g'", "b'"};
        for (int r = 0; r < 3; ++r) {
            ImGui::TableNextRow();
            for (int c = 0; c < 4; ++c) {
                ImGui::TableNextColumn();
                ImGui::PushID(r * 4 + c);
                float value = c < 3 ? t.matrix[c][r] : t.offset[r];
                ImGui::SetNextItemWidth(-1.0f);
                if (!editable) ImGui::BeginDisabled();
                if (ImGui::DragFloat("##cell", &value, 0.005f, -4.0f, 4.0f, c < 3 ? "%.4f" : "+%.4f")) {
                    if (c < 3) {
                        t.matrix[c][r] = value;
                    } else {
                        t.offset[r] = value;
                    }
                    changed = true;
                }
                if (!editable) ImGui::EndDisabled();
                if (ImGui::IsItemHovered())
                    ImGui::SetTooltip("%s: %s", rows[r], say(c < 3 ? "text.weight" : "text.offset").c_str());
                ImGui::PopID();
            }
        }
        ImGui::EndTable();
    }
    if (changed) {
        custom_ = t;
        preset_ = Custom;
    }
    ImGui::TextWrapped("%s", say(editable ? "text.matrixEditable" : "text.matrixFixed").c_str());
    ImGui::TextUnformatted(say(t.linear() ? "text.noOffset" : "text.hasOffset").c_str());
}

void ColourMatrixLesson::facts(Facts& out, const FrameInfo& frame) const {
    ColourTransform used = grading_->transform();
    out.add("transform", equations(used));
    out.add("needsOffset", !used.linear());
    out.add("whiteMapsTo", vec3Text(used.apply(glm::vec3(1.0f))));
    out.add("redMapsTo", vec3Text(used.apply(glm::vec3(1, 0, 0))));
    out.add("blackMapsTo", vec3Text(used.apply(glm::vec3(0.0f))));
    out.check("step", std::to_string(frame.step + 1));
}

}  // namespace lesson04

FX_LESSON(lesson04::ColourMatrixLesson, "Colour matrix", "scenes/04_colour_matrix.json")
