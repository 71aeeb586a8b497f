#include "effects/dof/dof_reference.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "effects/dof/dof_bindings.hpp"
#include "effects/scene/hdr_scene_pass.hpp"
#include "gl/framebuffer.hpp"
#include "gl/texture.hpp"
#include "render_gl/gl_state.hpp"
#include "render_gl/program_pass.hpp"

namespace fx {

// The scene's colour and depth for one aperture sample, at the target's size.
struct DofReference::Scratch {
    Size2D size;
    gl::Texture color, depth;
    gl::Framebuffer framebuffer;

    void ensure(Size2D wanted) {
        if (wanted == size && framebuffer.name() != 0) return;
        size = wanted;
        color = gl::Texture::create2D(TextureFormat::RGBA16F, size.width, size.height, 1,
                                      "dof reference sample colour");
        depth = gl::Texture::create2D(TextureFormat::Depth32F, size.width, size.height, 1,
                                      "dof reference sample depth");
        framebuffer = gl::Framebuffer("dof reference sample");
        framebuffer.attachColor(0, color);
        framebuffer.attachDepth(depth);
        framebuffer.setDrawBuffers(1);
    }
};

glm::vec2 apertureSample(int i, int n) {
    const float golden = 2.39996323f;  // pi (3 - sqrt 5)
    float r = std::sqrt((float(i) + 0.5f) / float(std::max(n, 1)));
    float a = golden * float(i);
    return {r * std::cos(a), r * std::sin(a)};
}

CameraMatrices jitteredCamera(const CameraMatrices& base, float fovYDegrees, float nearM, float farM,
                              glm::vec2 offset, float focusM) {
    CameraMatrices m = base;
    // Move the eye within its own right/up plane: view-space x and y shift by -offset.
    m.view = glm::translate(glm::mat4(1.0f), glm::vec3(-offset, 0.0f)) * base.view;
    glm::mat4 toWorld = glm::inverse(base.view);
    m.position = glm::vec3(toWorld * glm::vec4(offset, 0.0f, 1.0f));
    // Shear the frustum so that the focus plane keeps its pixels: at the near plane, by offset n / P.
    float top = nearM * std::tan(glm::radians(fovYDegrees) * 0.5f), right = top * base.aspect;
    glm::vec2 shift = offset * (nearM / std::max(focusM, 1e-6f));
    m.projection =
        glm::frustum(-right - shift.x, right - shift.x, -top - shift.y, top - shift.y, nearM, farM);
    m.viewProjection = m.projection * m.view;
    return m;
}

float referenceApertureRadiusM(float scalePixelsM, float radiusPerDiameter, float fovYDegrees,
                               int heightPixels) {
    float focalPixels = 0.5f * float(std::max(heightPixels, 1)) / std::tan(glm::radians(fovYDegrees) * 0.5f);
    return scalePixelsM * radiusPerDiameter / focalPixels;
}

DofReference::DofReference() : scratch_(std::make_shared<Scratch>()) {}

DeclaredPass DofReference::declare(FrameGraph& graph, const World& world, const DofReferenceSettings& s,
                                   std::optional<TextureHandle> into) const {
    const gl::ReloadableProgram* program = &scene_;
    const FullscreenPass* accumulate = &accumulate_;
    std::shared_ptr<Scratch> scratch = scratch_;
    Pass& pass = graph.addPass("dof reference", [program, accumulate, scratch, world, s](PassContext& ctx) {
        const Scene& scene = world.scene();
        GLint target = 0;
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &target);
        const Size2D size = ctx.targetSize();
        scratch->ensure(size);
        const CameraMatrices base = cameraMatrices(s.camera, size.width, size.height);
        const int n = std::max(s.samples, 1);
        PassState accumulateState = FullscreenPass::state();
        accumulateState.blend = true;
        accumulateState.blendFunction = BlendFunction::additive();
        const ClearColor sky = *hdrSceneState(scene).clearColor;
        const float one = 1.0f;
        const int first = std::clamp(s.firstSample, 0, n);
        const int last = s.sampleCount > 0 ? std::min(first + s.sampleCount, n) : n;
        for (int i = first; i < last; ++i) {
            glm::vec2 offset = apertureSample(i, n) * s.apertureRadiusM;
            CameraMatrices camera =
                jitteredCamera(base, s.camera.fovYDegrees, s.camera.near, s.camera.far, offset, s.focusM);
            glBindFramebuffer(GL_FRAMEBUFFER, scratch->framebuffer.name());
            applyGlState(hdrSceneState(scene), size);
            glClearNamedFramebufferfv(scratch->framebuffer.name(), GL_COLOR, 0, sky.data());
            glClearNamedFramebufferfv(scratch->framebuffer.name(), GL_DEPTH, 0, &one);
            SceneMeshes::setFrameUniforms(program->name(), scene, camera);
            glProgramUniform1f(program->name(), glsl::kHdrMaxLocation, kSceneHdrMax);
            world.draw(program->name());

            glBindFramebuffer(GL_FRAMEBUFFER, GLuint(target));
            applyGlState(accumulateState, size);
            glProgramUniform1f(accumulate->program(), glsl::kDofAccumulateWeightLocation, 1.0f / float(n));
            accumulate->draw({scratch->color.name()});
        }
    });
    TextureHandle out = into
                            ? *into
                            : pass.create("dof.reference", {TextureSize::output(), TextureFormat::RGBA32F, 1},
                                          TextureUsage::ColorAttachment);
    if (into) pass.modify(*into, TextureUsage::ColorAttachment);
    PassState state = FullscreenPass::state();
    state.blend = true;
    state.blendFunction = BlendFunction::additive();
    if (!into || s.firstSample == 0) state.clearColor = ClearColor{0.0f, 0.0f, 0.0f, 0.0f};
    // Per sample this frame draws: the scene's two material textures, then the sum's one (its scratch
    // targets are its own, outside the graph and the traffic model).
    const int samples = std::max(s.samples, 1);
    const int drawn = s.sampleCount > 0
                          ? std::min(s.sampleCount, samples - std::clamp(s.firstSample, 0, samples))
                          : samples;
    runsWith(pass.setState(state).setTaps(3.0 * std::max(drawn, 1)), scene_);
    runsWith(pass, accumulate_.reloadable());
    return {pass, out};
}

}  // namespace fx
