// Lesson 09: depth of field from a physical lens (the Depth of field chapter, docs/chapters.md): a
// framebuffer shown by a full-screen pass, the chapter's naive blur, focusing by moving the camera,
// the thin-lens CoC as a heat map, the chapter's 13-tap physical blur, then a near/far gather with a
// ring kernel at half resolution, and the accumulation reference it is measured against.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <imgui.h>
#include <glm/geometric.hpp>

#include "app/lesson.hpp"
#include "app/runner.hpp"
#include "base/log.hpp"
#include "effects/dof/depth_of_field.hpp"
#include "effects/dof/dof_reference.hpp"
#include "effects/dof/framebuffer_mistakes.hpp"
#include "effects/post/output_transform_pass.hpp"
#include "effects/scene/hdr_scene_pass.hpp"
#include "effects/scene/scene_meshes.hpp"
#include "effects/scene/scene_work.hpp"
#include "gl/texture.hpp"
#include "scene/scene_enums.hpp"
#include "scene/scene_settings.hpp"
#include "scene/thin_lens.hpp"

namespace lesson09 {

using namespace fx;

class DepthOfFieldLesson final : public Lesson {
public:
    std::vector<std::string> steps() const override;
    void declareParams(ParamSet& params) override;
    Status init(const Scene& scene) override;
    void buildFrame(FrameGraph& graph, const FrameInfo& frame) override;
    void drawPanel(const FrameInfo& frame) override;
    void facts(Facts& out, const FrameInfo& frame) const override;
    int benchStep() const override { return Beyond; }
    std::string benchReferenceName() const override { return "accumulation"; }
    void setBenchReference(bool on) override { benchReference_ = on; }

    enum Step { Framebuffer, Naive, MovedCamera, PhysicalCamera, ChapterShader, Beyond, Reference };

    // The camera the frame's step draws with (position and projection) at the frame's size.
    Camera cameraFor(const FrameInfo& frame) const;
    // The thin-lens model of the current parameters at the frame's size.
    ThinLensModel lensModel(const FrameInfo& frame) const;
    CocConvention convention() const {
        return chapterCompatible_ ? CocConvention::chapter : CocConvention::corrected;
    }

private:
    bool showsReference(int step) const { return step == Reference || (step == Beyond && benchReference_); }
    // In a window the reference's samples are spread over frames, as many a frame as the frame budget
    // holds, summed into referenceSum_ in the order one frame would sum them (the finished picture is
    // the headless one). Returns the sum; `exposure` is scaled to the mean of the samples so far.
    TextureHandle declareReferenceOverFrames(FrameGraph& graph, const FrameInfo& frame,
                                             DofReferenceSettings settings, float& exposure);

    // Parameters: the lens starts from the scene's camera.lens, the rest from postEffects.depthOfField.
    // A parameter bound to a scene setting takes the setting's default when it is declared
    // (ParamSet::addSetting), so those members have no default of their own here.
    float focalLengthMm_{};
    float sensorWidthMm_{};
    float fNumber_{};
    float focusM_{};
    bool chapterCompatible_ = false;
    float maxCoc_{};
    int taps_{};
    int method_ = 1;      // step 6: 0 the chapter's 13 taps, 1 the gather
    int resolution_ = 1;  // 0 full, 1 half
    int fields_ = 1;      // 0 one average, 1 near and far
    float highlight_ =
        0.0f;  // the reference has no such weighting: 0 by default, so the bench compares like with like
    int referenceSamples_ = 64;
    Choice<ToneCurve> toneCurve_{ToneCurve{}};
    float exposure_{};
    bool benchReference_ = false;
    // The mistakes the chapter warns about, shown on purpose (off by default).
    Choice<ShownTarget> shownTarget_{ShownTarget::color};                    // step 1
    Choice<IncompleteFramebuffer> incomplete_{IncompleteFramebuffer::none};  // step 1
    float cocNearM_ = 0.0f;  // steps 4 to 6: the CoC pass's near plane (0: the projection's)
    FramebufferCheck incompleteCheck_;
    IncompleteFramebuffer checkedKind_ = IncompleteFramebuffer::none;

    // The reference over frames (a window): its sum, what it is of, how far it is.
    gl::Texture referenceSum_;
    std::uint64_t referenceKey_ = 0;
    int referenceDone_ = 0;
    int referenceSlice_ = 0;       // samples the last frame added (0: none)
    double referenceSeconds_ = 0;  // the lesson clock's time the sum shows

    Scene view_;  // the scene with the step's camera (steps 1 to 3 move it, as the chapter does)
    Gpu<HdrScenePass> scenePass_;
    Gpu<DepthOfField> dof_;
    Gpu<DofReference> reference_;
    Gpu<OutputTransformPass> present_;
    Gpu<SamplingMistakes> samplingMistakes_;
    PassGroup dofGroup_ = groupNeeding(SceneFeature::depthOfField);
};

namespace {

// The chapter's first camera: 55.9 m from the player, looking at it through a 30 deg vertical field
// of view with near 1 m and far 1000 m (the projection its 0.935 was tuned for, at 15.264 m).
constexpr float kChapterFirstDistanceM = 55.9f;
constexpr float kChapterOldFovY = 30.0f, kChapterOldNear = 1.0f, kChapterOldFar = 1000.0f;

float aspectOf(Size2D size) {
    return size.width > 0 && size.height > 0 ? float(size.width) / float(size.height) : 1.0f;
}

}  // namespace

std::vector<std::string> DepthOfFieldLesson::steps() const {
    return {
        "Render to a framebuffer, show it with a full-screen pass",
        "The chapter's naive blur: raw depth minus 0.935",
        "Focus by moving the camera",
        "The physical camera: the circle of confusion as a heat map",
        "The chapter's physical shader: 13 taps scaled by the CoC",
        "Beyond the chapter: near and far fields, a ring kernel, half resolution",
        "The reference: accumulation over the aperture",
    };
}

void DepthOfFieldLesson::declareParams(ParamSet& params) {
    const std::vector<int> lensSteps = {PhysicalCamera, ChapterShader, Beyond, Reference};
    params.addSetting("focal_length", &focalLengthMm_, sceneSetting("camera.lens.focalLength"))
        .inSteps(lensSteps);
    params.addSetting("sensor_width", &sensorWidthMm_, sceneSetting("camera.lens.sensorWidth"))
        .inSteps(lensSteps);
    params.addSetting("f_number", &fNumber_, sceneSetting("camera.lens.fNumber")).inSteps(lensSteps);
    params.addSetting("focus_distance", &focusM_, sceneSetting("camera.lens.focusDistance"))
        .inSteps(lensSteps);
    params.addBool("chapter_compatible", &chapterCompatible_).inSteps(lensSteps);
    Param& maxCoc = params.addSetting("max_coc", &maxCoc_, sceneSetting("postEffects.depthOfField.maxCoc"));
    maxCoc.knob = Knob{{8, 16, 32, 64}, 64, "px"};
    maxCoc.inSteps({PhysicalCamera, ChapterShader, Beyond});
    Param& taps = params.addSetting("taps", &taps_, sceneSetting("postEffects.depthOfField.taps"));
    taps.knob = Knob{{16, 22, 43, 71}, 71, "taps"};
    taps.inSteps({Beyond});
    Param& method = params.addChoice("method", &method_, {"chapter", "gather"});
    method.knob = Knob{{0, 1}, 1, "method"};
    method.inSteps({Beyond});
    Param& resolution = params.addChoice("resolution", &resolution_, {"full", "half"});
    resolution.knob = Knob{{0, 1}, 0, "resolution"};
    resolution.inSteps({Beyond});
    Param& fields = params.addChoice("fields", &fields_, {"one", "near-far"});
    fields.knob = Knob{{0, 1}, 1, "fields"};
    fields.inSteps({Beyond});
    params.addFloat("highlight", &highlight_, 0.0f, 8.0f).inSteps({Beyond});
    params.addInt("reference_samples", &referenceSamples_, 1, 1024).inSteps({Reference});
    // The mistakes the chapter warns about, made on purpose (off by default).
    params
        .addChoice("shown_target", &shownTarget_,
                   {"colour", "colour-mipmap-min-filter", "depth", "depth-compare-mode"})
        .inSteps({Framebuffer});
    params.addChoice("incomplete_fbo", &incomplete_, {"none", "rgb9e5-colour", "no-attachment"})
        .inSteps({Framebuffer});
    params.addFloat("coc_near", &cocNearM_, 0.0f, 5.0f)
        .showZeroAs()
        .inSteps({PhysicalCamera, ChapterShader, Beyond});
    params.addSetting("tone_map", &toneCurve_, sceneSetting("postEffects.toneMap.operator"));
    params.addSetting("exposure", &exposure_, sceneSetting("postEffects.toneMap.exposure"));
}

Status DepthOfFieldLesson::init(const Scene& scene) {
    view_ = scene;
    return Status::success();
}

ThinLensModel DepthOfFieldLesson::lensModel(const FrameInfo& frame) const {
    const Size2D size = frame.size;
    ThinLensInput in;
    in.lens = Lens{focalLengthMm_, sensorWidthMm_, fNumber_, focusM_};
    in.nearM = frame.world.scene().camera.near;
    in.farM = frame.world.scene().camera.far;
    in.widthPixels = size.width;
    in.maxCocPixels = maxCoc_;
    in.convention = convention();
    return thinLensModel(in);
}

Camera DepthOfFieldLesson::cameraFor(const FrameInfo& frame) const {
    const int step = frame.step;
    const Size2D size = frame.size;
    Camera camera = frame.world.scene().camera;
    camera.lens.reset();
    if (step <= Naive) {
        // The chapter's first camera: the same line of sight, 55.9 m from the point it looks at.
        glm::vec3 dir = viewDirection(camera);
        glm::vec3 target = camera.aim == CameraAim::target ? camera.target : camera.position + dir * focusM_;
        camera.position = target - dir * kChapterFirstDistanceM;
        camera.target = target;
        camera.aim = CameraAim::target;
    }
    if (step <= MovedCamera) {
        camera.fovYDegrees = kChapterOldFovY;
        camera.near = kChapterOldNear;
        camera.far = kChapterOldFar;
    } else {
        Lens lens{std::clamp(focalLengthMm_, float(kMinFocalMm), float(kMaxFocalMm)), sensorWidthMm_,
                  fNumber_, focusM_};
        camera.fovYDegrees = dofVerticalFovDegrees(lens, convention(), aspectOf(size));
    }
    return camera;
}

void DepthOfFieldLesson::buildFrame(FrameGraph& graph, const FrameInfo& frame) {
    const int step = frame.step;
    view_.camera = cameraFor(frame);
    HdrSceneTargets hdr = scenePass_->declare(graph, frame.world.seenThrough(view_));
    const ThinLensModel model = lensModel(frame);
    DofLensUniforms lens = dofLensUniforms(model);
    if (cocNearM_ > 0.0f) lens.nearM = cocNearM_;  // the depth is still the projection's
    const bool calledFor = !lacks(graph, SceneFeature::depthOfField);
    TextureHandle shown = hdr.color;
    ToneCurve curve = *toneCurve_;
    float exposure = exposure_;
    {
        PassGroup::Scope in(graph, dofGroup_);  // not called for when the scene has no depth of field
        if (step == Framebuffer) {
            shown = samplingMistakes_->declare(graph, hdr.color, hdr.depth, *shownTarget_, frame.size);
            if (*shownTarget_ == ShownTarget::depth || *shownTarget_ == ShownTarget::depthCompareMode) {
                curve = ToneCurve::clip;  // depth as grey, for the display
                exposure = 1.0f;
            }
        } else if (step == Naive || step == MovedCamera) {
            shown = dof_->declareNaive(graph, hdr.color, hdr.depth, {}).output;
        } else if (step >= PhysicalCamera) {
            TextureHandle coc = dof_->declareCoc(graph, hdr.depth, lens).output;
            if (step == PhysicalCamera) {
                shown = dof_->declareHeatMap(graph, hdr.color, coc, lens).output;
                curve = ToneCurve::clip;  // the heat map's colours are display colours
                exposure = 1.0f;
            } else if (step == ChapterShader || (step == Beyond && method_ == 0 && !benchReference_)) {
                shown = dof_->declareChapter(graph, hdr.color, coc, lens).output;
            } else if (showsReference(step)) {
                DofReferenceSettings r;
                r.camera = view_.camera;
                r.apertureRadiusM =
                    referenceApertureRadiusM(float(model.scalePixelsM), float(model.radiusPerDiameter),
                                             r.camera.fovYDegrees, frame.size.height);
                r.focusM = float(model.focusM);
                r.samples = referenceSamples_;
                // Headless and in the bench all samples in one frame; in a window, a budget's worth a frame.
                shown = frame.frameBudgetMs > 0 && !frame.benchmark
                            ? declareReferenceOverFrames(graph, frame, r, exposure)
                            : reference_->declare(graph, frame.world.seenThrough(view_), r).output;
            } else {
                DofGatherSettings g{taps_, resolution_ == 1, fields_ == 1, highlight_};
                shown = dof_->declareGather(graph, hdr.color, coc, lens, g).result;
            }
        }
    }
    present_->declare(graph, calledFor ? shown : hdr.color, std::nullopt, curve, exposure);
    if (step == Framebuffer && *incomplete_ != checkedKind_) {
        incompleteCheck_ = checkIncompleteFramebuffer(*incomplete_);  // built, checked, deleted: no draw
        checkedKind_ = *incomplete_;
    }
}

TextureHandle DepthOfFieldLesson::declareReferenceOverFrames(FrameGraph& graph, const FrameInfo& frame,
                                                             DofReferenceSettings r, float& exposure) {
    // Anything that changes the picture starts the sum again: the camera, the aperture, the count, the size.
    std::uint64_t key = 1469598103934665603ull;
    for (double v : {double(r.camera.position.x), double(r.camera.position.y), double(r.camera.position.z),
                     double(r.camera.target.x), double(r.camera.target.y), double(r.camera.target.z),
                     double(r.camera.fovYDegrees), double(r.apertureRadiusM), double(r.focusM),
                     double(r.samples), double(frame.size.width), double(frame.size.height)})
        key = (key ^ std::hash<double>{}(v)) * 1099511628211ull;
    if (key != referenceKey_ || !referenceSum_) {
        referenceSum_ = gl::Texture::create2D(TextureFormat::RGBA32F, frame.size.width, frame.size.height, 1,
                                              "dof.reference (summed over frames)");
        referenceKey_ = key;
        referenceDone_ = 0;
        referenceSlice_ = 0;
        referenceSeconds_ = frame.seconds;  // every slice renders the moment the sum started
    }
    TextureHandle sum = graph.importTexture("dof.reference", referenceSum_.spec(), referenceSum_.name());
    const int n = std::max(r.samples, 1);
    if (referenceDone_ < n) {
        // As many samples as half the budget holds, by what a sample cost last frame (one, to find out).
        int count = 1;
        if (referenceSlice_ > 0 && frame.previousFrame) {
            const double perSample = dofGroup_.timeMs(*frame.previousFrame) / referenceSlice_;
            if (perSample > 0) count = int(0.5 * frame.frameBudgetMs / perSample);
        }
        r.firstSample = referenceDone_;
        r.sampleCount = std::clamp(count, 1, n - referenceDone_);
        reference_->declare(graph, World(view_, frame.world.meshes(), referenceSeconds_), r, sum);
        referenceDone_ += r.sampleCount;
        referenceSlice_ = r.sampleCount;
    } else {
        referenceSlice_ = 0;
    }
    // The sum holds done / n of the picture: shown as the mean of the samples so far.
    exposure *= float(n) / float(referenceDone_);
    return sum;
}

void DepthOfFieldLesson::drawPanel(const FrameInfo& frame) {
    if (frame.step == PhysicalCamera) ImGui::TextWrapped("%s", say("text.cocColours").c_str());
    if (frame.step >= PhysicalCamera) ImGui::TextWrapped("%s", say("text.inspectCoc").c_str());
}

void DepthOfFieldLesson::facts(Facts& out, const FrameInfo& frame) const {
    const int step = frame.step;
    const Camera camera = cameraFor(frame);
    out.add("cameraDistance", cat(glm::length(camera.target - camera.position)));
    out.add("projection", cat(camera.fovYDegrees, " deg, near ", camera.near, ", far ", camera.far));
    if (step == Framebuffer && *incomplete_ != IncompleteFramebuffer::none) {
        out.add("incompleteFboStatus", incompleteCheck_.status);
        out.add("incompleteFboMessage", incompleteCheck_.message);
    }
    if (step < PhysicalCamera) {
        out.add("targetDepth",
                cat(windowDepth(glm::length(camera.target - camera.position), camera.near, camera.far)));
        return;
    }
    const ThinLensModel m = lensModel(frame);
    out.add("convention", chapterCompatible_ ? "chapter-compatible" : "corrected");
    out.add("focus", cat(m.focusM));
    out.add("focalLength", cat(m.focalMm));
    out.add("imageDistance", cat(m.imageMm));
    out.add("aperture", cat(m.apertureMm));
    for (double d : {1.0, 2.0, 5.0, 50.0, 250.0})
        out.addAs(cat("coc", int(d), "m"), "cocAt", cat(signedCocPixels(m, d)), {{"d", cat(d)}});
    if (cocNearM_ > 0.0f && step != Reference) {
        // The depth the projection wrote at the focus distance, read back with the CoC pass's near plane.
        const double readAs =
            linearDepthM(windowDepth(m.focusM, camera.near, camera.far), cocNearM_, camera.far);
        const double focusLands =
            linearDepthM(windowDepth(m.focusM, cocNearM_, camera.far), camera.near, camera.far);
        out.add("cocNear", cat(cocNearM_, " m (the projection's: ", camera.near, " m)"));
        out.add("focusReadAs", cat(readAs));
        out.add("focusLandsAt", cat(focusLands));
    }
    out.add("blurRadiusAt1m", cat(std::abs(signedCocPixels(m, 1.0)) * m.radiusPerDiameter));
    if (step == Beyond) out.add("kernelTaps", cat(dofKernelForTaps(taps_).taps));
    if (showsReference(step)) {
        // In a window the samples come a frame's budget at a time: how far the sum is.
        if (frame.frameBudgetMs > 0 && !frame.benchmark)
            out.progressAs("referenceSamples", "referenceSamplesSummed", referenceDone_,
                           std::max(referenceSamples_, 1));
        else
            out.add("referenceSamples", cat(referenceSamples_));
    }
    if (frame.previousFrame) out.add("dofMs", cat(dofGroup_.timeMs(*frame.previousFrame)));
}

}  // namespace lesson09

FX_LESSON(lesson09::DepthOfFieldLesson, "Depth of field", "scenes/09_depth_of_field.json")
