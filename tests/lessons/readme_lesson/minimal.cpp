// lessons/00_minimal/minimal.cpp: the scene lit in linear HDR, then one output transform.
#include "app/runner.hpp"
#include "effects/post/output_transform_pass.hpp"
#include "effects/scene/hdr_scene_pass.hpp"

using namespace fx;

class MinimalLesson final : public Lesson {
public:
    std::vector<std::string> steps() const override { return {"The scene"}; }

    void buildFrame(FrameGraph& graph, const FrameInfo& frame) override {
        HdrSceneTargets hdr = scenePass_->declare(graph, frame.world);
        present_->declare(graph, hdr.color);
    }

private:
    Gpu<HdrScenePass> scenePass_;
    Gpu<OutputTransformPass> present_;
};

FX_LESSON(MinimalLesson, "Minimal", "scenes/04_colour_matrix.json")
