#include "effects/deferred/gbuffer_pass.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include "base/log.hpp"
#include "effects/deferred/output_check.hpp"
#include "effects/scene/hdr_scene_pass.hpp"
#include "render_gl/program_pass.hpp"

namespace fx {

CameraMatrices offsetCameraMatrices(const Camera& camera, glm::vec3 offset, Size2D size) {
    Camera moved = camera;
    moved.position += offset;
    moved.target += offset;
    return cameraMatrices(moved, size.width, size.height);
}

const gl::ReloadableProgram& GBufferPass::program(GBufferLayout layout, bool referencePosition) const {
    const int layoutNumber = static_cast<int>(layout);
    std::optional<gl::ReloadableProgram>& slot = programs_[layoutNumber * 2 + (referencePosition ? 1 : 0)];
    if (!slot) {
        std::string defines = cat("#define LAYOUT ", layoutNumber, "\n");
        if (referencePosition) {
            // The next colour attachment after the layout's own targets.
            int location = gbufferFormats(layout).position ? 3 : 2;
            defines += cat("#define REFERENCE_POSITION 1\n#define REFERENCE_LOCATION ", location, "\n");
        }
        slot.emplace(gl::ProgramSources{
            "effects/deferred/lit_scene.vert",
            "effects/deferred/gbuffer.frag",
            {},
            defines,
            cat("gbuffer (", toString(layout), referencePosition ? ", reference" : "", ")")});
    }
    return *slot;
}

GBufferTargets GBufferPass::declare(FrameGraph& graph, const World& world,
                                    const GBufferOptions& options) const {
    const gl::ReloadableProgram* prog = &program(options.layout, options.referencePosition);
    const glm::vec3 offset = options.worldOffset;
    Pass& pass = graph.addPass("gbuffer", [prog, world, offset](PassContext& ctx) {
        CameraMatrices camera = offsetCameraMatrices(world.scene().camera, offset, ctx.targetSize());
        SceneMeshes::setFrameUniforms(prog->name(), world.scene(), camera);
        checkOutputsOnce(prog->name(), "gbuffer");
        MeshDrawOptions draw;
        draw.placement = glm::translate(glm::mat4(1.0f), offset);
        world.draw(prog->name(), draw);
    });
    GBufferFormats f = gbufferFormats(options.layout);
    GBufferTargets t;
    t.layout = options.layout;
    t.worldOffset = offset;
    // Colour attachments in declaration order: albedo 0, normal 1, position 2, reference next.
    t.albedo =
        pass.create("gbuffer.albedo", {TextureSize::output(), f.albedo, 1}, TextureUsage::ColorAttachment);
    t.normal =
        pass.create("gbuffer.normal", {TextureSize::output(), f.normal, 1}, TextureUsage::ColorAttachment);
    if (f.position)
        t.position = pass.create("gbuffer.position", {TextureSize::output(), *f.position, 1},
                                 TextureUsage::ColorAttachment);
    if (options.referencePosition)
        t.referencePosition =
            pass.create("gbuffer.reference_position", {TextureSize::output(), TextureFormat::RGBA32F, 1},
                        TextureUsage::ColorAttachment);
    t.depth =
        pass.create("gbuffer.depth", {TextureSize::output(), f.depth, 1}, TextureUsage::DepthAttachment);
    PassState state = hdrSceneState(world.scene());
    state.clearColor = ClearColor{0, 0, 0, 0};         // alpha 0 in albedo: no surface
    runsWith(pass.setState(state).setTaps(1), *prog);  // the base colour
    return t;
}

}  // namespace fx
