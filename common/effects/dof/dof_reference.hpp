#pragma once
// The depth-of-field reference: accumulation over the aperture. The scene is rendered `samples` times
// through pinholes spread over the lens's aperture disk (a Vogel spiral: even coverage, no random
// numbers), each with its frustum sheared so that the focus plane lands on the same pixels, and the
// renders are averaged. That is the thin lens exactly, occlusion included (a near object hides what
// is behind it from part of the aperture only), up to the sampling of the aperture: a point blurred
// to radius r is `samples` copies spaced about r sqrt(pi / samples) apart.
//
// One pass, "dof reference", writes dof.reference (RGBA32F, cleared to 0, additive). Inside it the
// scene goes into a scratch colour and depth target of its own (labelled), once per sample.
#include <memory>
#include <optional>

#include <glm/vec2.hpp>

#include "effects/post/fullscreen_pass.hpp"
#include "effects/scene/camera_matrices.hpp"
#include "effects/scene/world.hpp"
#include "render/frame_graph.hpp"

namespace fx {

// Sample i of n on the unit disk (golden-angle spiral; the first sample is near the centre).
glm::vec2 apertureSample(int i, int n);

// The camera seen through the point `lensOffsetM` (metres, in the camera's right/up plane) of the
// aperture, its frustum sheared so that points at the planar distance `focusM` keep their pixels.
// `base` is the pinhole camera (view and a symmetric projection of `fovYDegrees`).
CameraMatrices jitteredCamera(const CameraMatrices& base, float fovYDegrees, float nearM, float farM,
                              glm::vec2 lensOffsetM, float focusM);

// The aperture radius (m) that blurs a point at distance D to the radius the CoC model gives:
// K * radiusPerDiameter / (the projection's focal length in pixels), for a target `heightPixels` high.
float referenceApertureRadiusM(float scalePixelsM, float radiusPerDiameter, float fovYDegrees,
                               int heightPixels);

struct DofReferenceSettings {
    Camera camera;  // the pinhole camera: fovYDegrees is the projection's, lens unused
    float apertureRadiusM = 0.0f;
    float focusM = 10.0f;
    int samples = 64;
    // A share of the samples, for a reference spread over several frames (a window's frame budget):
    // samples [firstSample, firstSample + sampleCount) of `samples`, each weighted 1 / samples. 0: all.
    int firstSample = 0;
    int sampleCount = 0;
};

class DofReference {
public:
    DofReference();  // in the .cpp, where Scratch is complete
    // `world` must outlive the frame's execution. `into`: add the samples into this texture (kept from
    // frame to frame, RGBA32F; cleared first when firstSample is 0) instead of a new dof.reference, so
    // that a reference spread over frames sums its samples in the same order.
    DeclaredPass declare(FrameGraph& graph, const World& world, const DofReferenceSettings& settings,
                         std::optional<TextureHandle> into = {}) const;

private:
    struct Scratch;
    gl::ReloadableProgram scene_{
        {"effects/scene/scene_hdr.vert", "effects/scene/scene_hdr.frag", {}, {}, "dof reference scene"}};
    FullscreenPass accumulate_{"effects/dof/accumulate.frag", "dof reference accumulate"};
    std::shared_ptr<Scratch> scratch_;
};

}  // namespace fx
