#include "effects/scene/hdr_scene_pass.hpp"

#include <algorithm>

#include "effects/scene/camera_matrices.hpp"
#include "image/view_transform.hpp"
#include "render_gl/program_pass.hpp"

namespace fx {

PassState hdrSceneState(const Scene& scene) {
    // The sky is linear HDR like everything else in the scene file; it obeys the same limit.
    auto sky = [](float c) { return std::clamp(c, 0.0f, kSceneHdrMax); };
    return {.depthTest = true,
            .depthWrite = true,
            .depthFunction = DepthFunction::Less,
            .blend = false,
            .faceCulling = true,
            .cullFace = CullFace::Back,
            .colorMask = ColorMask{},
            .clearColor =
                ClearColor{sky(scene.background.r), sky(scene.background.g), sky(scene.background.b), 1.0f},
            .clearDepth = 1.0f};
}

ClearColor displayClearColor(const Scene& scene) {
    auto encode = [](float c) { return float(encodeSrgb(std::clamp(double(c), 0.0, 1.0))); };
    return {encode(scene.background.r), encode(scene.background.g), encode(scene.background.b), 1.0f};
}

HdrSceneTargets HdrScenePass::declare(FrameGraph& graph, const World& world,
                                      TextureFormat colorFormat) const {
    const gl::ReloadableProgram* program = &program_;
    Pass& pass = graph.addPass("scene", [program, world](PassContext& ctx) {
        Size2D size = ctx.targetSize();
        CameraMatrices camera = cameraMatrices(world.scene().camera, size.width, size.height);
        GLuint name = program->name();
        SceneMeshes::setFrameUniforms(name, world.scene(), camera);
        glProgramUniform1f(name, glsl::kHdrMaxLocation, kSceneHdrMax);
        world.draw(name);
    });
    HdrSceneTargets targets;
    targets.color =
        pass.create("scene.color", {TextureSize::output(), colorFormat, 1}, TextureUsage::ColorAttachment);
    targets.depth = pass.create("scene.depth", {TextureSize::output(), TextureFormat::Depth32F, 1},
                                TextureUsage::DepthAttachment);
    // Taps: the material's base colour and emissive textures.
    runsWith(pass.setState(hdrSceneState(world.scene())).setTaps(2), program_);
    return targets;
}

}  // namespace fx
