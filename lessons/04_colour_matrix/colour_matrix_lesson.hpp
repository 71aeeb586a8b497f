#pragma once
// Lesson 04: colour matrix (the Shader effects chapter, §3.4, §3.5, hard cases 5 to 8, Exercise 02).
#include "app/lesson.hpp"
#include "app/point_drag.hpp"
#include "effects/post/colour_matrix.hpp"
#include "effects/post/output_transform_pass.hpp"
#include "effects/scene/hdr_scene_pass.hpp"
#include "effects/scene/scene_meshes.hpp"
#include "effects/scene/scene_work.hpp"

namespace lesson04 {

class ColourMatrixLesson final : public fx::Lesson {
public:
    fx::LessonInfo info() const override;
    std::vector<std::string> steps() const override;
    void declareParams(fx::ParamSet& params) override;
    void update(const fx::FrameInfo& frame) override;
    void buildFrame(fx::FrameGraph& graph, const fx::FrameInfo& frame) override;
    void drawPanel(const fx::FrameInfo& frame) override;
    void facts(fx::Facts& out, const fx::FrameInfo& frame) const override;

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
    float amount_ = 1.0f;
    float saturation_ = 1.8f;
    float hueDegrees_ = 120.0f;
    int channelOrder_ = 3;  // "gbr"
    float brightness_ = 0.1f;
    float contrast_ = 1.4f;
    bool splitView_ = true;
    float divider_ = 0.72f;  // right of the blue cylinder: every object but the capsule is processed

    fx::Gpu<fx::HdrScenePass> scenePass_;
    fx::Gpu<fx::ColourMatrixPass> grading_;
    fx::Gpu<fx::OutputTransformPass> present_;
    fx::ColourTransform custom_;  // the matrix edited in the overlay (preset "custom")
    fx::PassGroup gradingGroup_ = fx::groupNeeding(fx::SceneFeature::colorMatrix);
    fx::PointDrag dividerDrag_;

    // The transform the step (and, in step 4, the preset) selects, before `amount`.
    fx::ColourTransform selected(int step) const;
    fx::ColourTransform presetTransform(int preset) const;
};

}  // namespace lesson04
