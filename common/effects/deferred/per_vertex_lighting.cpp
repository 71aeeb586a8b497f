#include "effects/deferred/per_vertex_lighting.hpp"

#include "effects/deferred/deferred_bindings.hpp"
#include "effects/scene/camera_matrices.hpp"
#include "effects/scene/hdr_scene_pass.hpp"
#include "effects/scene/scene_meshes.hpp"
#include "render_gl/program_pass.hpp"

namespace fx {

TextureHandle PerVertexLighting::declare(FrameGraph& graph, const World& world,
                                         const PointLightBuffer& lights) const {
    const gl::ReloadableProgram* program = &program_;
    const PointLightBuffer* buffer = &lights;
    Pass& pass = graph.addPass("per-vertex lighting", [program, buffer, world](PassContext& ctx) {
        Size2D size = ctx.targetSize();
        CameraMatrices camera = cameraMatrices(world.scene().camera, size.width, size.height);
        GLuint p = program->name();
        SceneMeshes::setFrameUniforms(p, world.scene(), camera);
        glProgramUniform1f(p, glsl::kHdrMaxLocation, kSceneHdrMax);
        glProgramUniform1i(p, glsl::kPointLightCountLocation, buffer->count());
        buffer->bind();
        world.draw(p);
    });
    TextureHandle color =
        pass.create("forward.per_vertex", {TextureSize::output(), TextureFormat::RGBA16F, 1},
                    TextureUsage::ColorAttachment);
    pass.create("forward.depth", {TextureSize::output(), TextureFormat::Depth32F, 1},
                TextureUsage::DepthAttachment);
    pass.setState(hdrSceneState(world.scene())).setTaps(1);  // the base colour; the light came per vertex
    runsWith(pass, program_);
    return color;
}

}  // namespace fx
