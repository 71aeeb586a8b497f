#include "effects/deferred/lecture_mrt.hpp"

#include <algorithm>

#include "effects/deferred/deferred_bindings.hpp"
#include "effects/deferred/output_check.hpp"
#include "effects/scene/camera_matrices.hpp"
#include "effects/scene/hdr_scene_pass.hpp"
#include "gl/debug_output.hpp"
#include "render_gl/program_pass.hpp"

namespace fx {
namespace {

void setSky(GLuint program, const Scene& scene) {
    auto sky = [](float c) { return std::clamp(c, 0.0f, kSceneHdrMax); };
    glProgramUniform3f(program, glsl::kMrtSkyLocation, sky(scene.background.r), sky(scene.background.g),
                       sky(scene.background.b));
}

}  // namespace

void setLectureLight(GLuint program) {
    glProgramUniform3f(program, glsl::kLightColorLocation, 1.0f, 1.0f, 1.0f);
    glProgramUniform3f(program, glsl::kAmbientLocation, 0.2f, 0.2f, 0.2f);
}

MrtTargets LectureMrt::declare(FrameGraph& graph, const World& world, MrtOrder order, MrtStats* stats) const {
    const gl::ReloadableProgram* program = &phong_;
    Pass& pass = graph.addPass("mrt", [program, world, order, stats](PassContext& ctx) {
        Size2D size = ctx.targetSize();
        CameraMatrices camera = cameraMatrices(world.scene().camera, size.width, size.height);
        SceneMeshes::setFrameUniforms(program->name(), world.scene(), camera);
        setLectureLight(program->name());
        checkOutputsOnce(program->name(), "mrt");
        world.draw(program->name());
        if (order == MrtOrder::slides) {
            // The slides' step 6, while their framebuffer object is still bound.
            gl::ExpectedErrorScope expected("the slides restore GL_BACK with the FBO still bound");
            std::int64_t before = gl::debugCounters().expectedErrors;
            glDrawBuffer(GL_BACK);
            gl::drainErrorFlags();  // where there is no debug output, glGetError finds it
            if (stats) {
                stats->lastFrameErrors = gl::debugCounters().expectedErrors - before;
                stats->orderErrors += stats->lastFrameErrors;
            }
        } else if (stats) {
            stats->lastFrameErrors = 0;
        }
    });
    MrtTargets t;
    const TextureDesc rgba8{TextureSize::output(), TextureFormat::RGBA8, 1};
    t.diffuse = pass.create("mrt.diffuse", rgba8, TextureUsage::ColorAttachment);
    t.specular = pass.create("mrt.specular", rgba8, TextureUsage::ColorAttachment);
    t.ambient = pass.create("mrt.ambient", rgba8, TextureUsage::ColorAttachment);
    t.depth = pass.create("mrt.depth", {TextureSize::output(), TextureFormat::Depth32F, 1},
                          TextureUsage::DepthAttachment);
    PassState state = hdrSceneState(world.scene());
    state.clearColor = ClearColor{0, 0, 0, 0};          // every target; the composite adds the sky once
    runsWith(pass.setState(state).setTaps(2), phong_);  // base colour and emissive textures
    return t;
}

TextureHandle LectureMrt::declareComposite(FrameGraph& graph, const Scene& scene, const MrtTargets& t) const {
    const FullscreenPass* composite = &composite_;
    Pass& pass = composite_.addPass(graph, "mrt composite", [composite, &scene, t](PassContext& ctx) {
        setSky(composite->program(), scene);
        composite->draw({ctx.native(t.diffuse), ctx.native(t.specular), ctx.native(t.ambient)});
    });
    pass.read(t.diffuse).read(t.specular).read(t.ambient).setTaps(3);
    return pass.create("mrt.sum", {TextureSize::output(), TextureFormat::RGBA16F, 1},
                       TextureUsage::ColorAttachment);
}

SharpenTargets LectureMrt::declareSharpen(FrameGraph& graph, const Scene& scene, const MrtTargets& t) const {
    const FullscreenPass* sharpen = &sharpen_;
    Pass& pass = sharpen_.addPass(graph, "mrt sharpen", [sharpen, &scene, t](PassContext& ctx) {
        setSky(sharpen->program(), scene);
        sharpen->draw({ctx.native(t.diffuse), ctx.native(t.specular), ctx.native(t.ambient)});
    });
    // The diffuse term and its four neighbours (identity minus the Laplacian), then specular and ambient.
    pass.read(t.diffuse).read(t.specular).read(t.ambient).setTaps(7);
    SharpenTargets s;
    s.clipped = pass.create("sharpen.rgba8", {TextureSize::output(), TextureFormat::RGBA8, 1},
                            TextureUsage::ColorAttachment);
    s.kept = pass.create("sharpen.float", {TextureSize::output(), TextureFormat::RGBA16F, 1},
                         TextureUsage::ColorAttachment);
    return s;
}

TextureHandle LectureMrt::declareRangeView(FrameGraph& graph, const SharpenTargets& s) const {
    const FullscreenPass* range = &range_;
    Pass& pass = range_.addPass(graph, "sharpen range", [range, s](PassContext& ctx) {
        range->draw({ctx.native(s.clipped), ctx.native(s.kept)});
    });
    pass.read(s.clipped).read(s.kept).setTaps(2);
    return pass.create("sharpen.range", {TextureSize::output(), TextureFormat::RGBA16F, 1},
                       TextureUsage::ColorAttachment);
}

}  // namespace fx
