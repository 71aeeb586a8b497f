#pragma once
// Lesson 10: render to texture, multiple render targets and deferred shading with a thousand lights
// (the Deferred rendering chapter, docs/chapters.md). The slides' framebuffer recipes first, then their
// three-target example with its draw-buffer order bug and its sharpening variant, then what the chapter
// only lists: a G-buffer of geometry, one lighting pass over many point lights, what the G-buffer's
// layout costs, tiled light culling, and the chapter's homework, a planar reflection.
#include <string>
#include <vector>

#include "app/lesson.hpp"
#include "effects/deferred/deferred_lighting.hpp"
#include "effects/deferred/gbuffer_pass.hpp"
#include "effects/deferred/lecture_mrt.hpp"
#include "effects/deferred/planar_reflection.hpp"
#include "effects/deferred/point_light_buffer.hpp"
#include "effects/deferred/render_to_texture.hpp"
#include "effects/deferred/tiled_culling.hpp"
#include "effects/post/fullscreen_pass.hpp"
#include "effects/post/output_transform_pass.hpp"
#include "effects/scene/scene_meshes.hpp"
#include "effects/shadow/shadow_map.hpp"

namespace lesson10 {

class DeferredShadingLesson final : public fx::Lesson {
public:
    fx::LessonInfo info() const override;
    std::vector<std::string> steps() const override;
    void declareParams(fx::ParamSet& params) override;
    fx::Status init(const fx::Scene& scene) override;
    void buildFrame(fx::FrameGraph& graph, const fx::FrameInfo& frame) override;
    void facts(fx::Facts& out, const fx::FrameInfo& frame) const override;
    void drawPanel(const fx::FrameInfo& frame) override;
    int benchStep() const override { return Reflection; }
    std::string benchTexture() const override { return "deferred.color"; }

    enum Step { RenderToTexture, ThreeTargets, Sharpen, Deferred, Layout, ManyLights, Reflection };

private:
    // The G-buffer layout, light count and culling the step uses.
    fx::GBufferLayout layoutFor(int step) const;
    bool culls(int step) const { return step >= ManyLights; }
    glm::vec3 worldOffsetFor(int step) const;
    void uploadLights(const fx::FrameInfo& frame);
    void declareDeferred(fx::FrameGraph& graph, const fx::FrameInfo& frame, fx::TextureHandle& shown,
                         std::optional<fx::SplitView>& split);

    // Parameters.
    int rttDepth_ = 0;         // fx::RttDepth
    bool slidesOrder_ = true;  // step 2: the slides' glDrawBuffer(GL_BACK) with the FBO bound
    int layout_ = 0;           // fx::GBufferLayout
    int originOffset_ = 0;     // index into kOriginOffsets
    int lightCount_ = fx::kMaxGridLights;
    int culling_ = 1;         // 0 none, 1 tiled
    int reflectionSize_ = 1;  // index into kReflectionFractions
    float divider_ = 0.5f;

    std::vector<fx::Light> allLights_;
    int pointLightsInScene_ = 0;
    glm::vec3 uploadedOffset_{-1.0f};
    int uploadedCount_ = -1;
    fx::Gpu<fx::RenderToTexture> rtt_;
    fx::Gpu<fx::FullscreenPass> rttToScreen_{"common/copy.frag", "rtt to screen"};
    fx::Gpu<fx::LectureMrt> mrt_;
    fx::MrtStats mrtStats_;
    fx::Gpu<fx::GBufferPass> gbuffer_;
    fx::Gpu<fx::ShadowMap> shadows_;
    fx::Gpu<fx::PointLightBuffer> lights_;
    fx::Gpu<fx::DeferredLighting> lighting_;
    fx::Gpu<fx::TiledCulling> culling_pass_;
    fx::Gpu<fx::PlanarReflection> reflection_;
    fx::Gpu<fx::OutputTransformPass> present_;
    std::string rttAttachments_[2];
    fx::PassGroup cullingGroup_;
    fx::PassGroup lightingGroup_;
    fx::PassGroup reflectionGroup_;
};

}  // namespace lesson10
