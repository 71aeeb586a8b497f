#include "lit_scene_pass.hpp"

#include <algorithm>

#include "effects/scene/camera_matrices.hpp"
#include "image/view_transform.hpp"
#include "render_gl/program_pass.hpp"

namespace fx::glsl {
#include "shaders/lessons/03_fbo_pipeline/scene_lit_bindings.glsl"
}  // namespace fx::glsl

namespace lesson03 {

using namespace fx;

namespace {

// What the 3D draw depends on (effects/scene/hdr_scene_pass.hpp), declared by the pass itself from step 3
// on. Its clears are the target's: the window's and the float target's skies differ.
PassState sceneDrawState(const Scene& scene) {
    PassState state = hdrSceneState(scene);
    state.clearColor.reset();
    state.clearDepth.reset();
    return state;
}

}  // namespace

ClearColor LitScenePass::windowClearColor(const Scene& scene) {
    auto encode = [](float c) { return float(encodeSrgb(std::clamp(double(c), 0.0, 1.0))); };
    return {encode(scene.background.r), encode(scene.background.g), encode(scene.background.b), 1.0f};
}

Pass& LitScenePass::addPass(FrameGraph& graph, const World& world, const DeclaredShadowMap& shadow,
                            const LitSceneOptions& options) const {
    const gl::ReloadableProgram* program = &program_;
    // The lookup's uniforms need the map's GL name, which exists only while the frame runs.
    bool hasMap = shadow.pass != nullptr;
    TextureHandle map = shadow.map;
    ShadowLookup lookup = shadow.lookup;
    bool encode = options.encodeForDisplay;
    Pass& pass = graph.addPass(options.passName, [=](PassContext& ctx) {
        Size2D size = ctx.targetSize();
        CameraMatrices camera = cameraMatrices(world.scene().camera, size.width, size.height);
        GLuint name = program->name();
        SceneMeshes::setFrameUniforms(name, world.scene(), camera);
        glProgramUniform1f(name, glsl::kHdrMaxLocation, kSceneHdrMax);
        glProgramUniform1i(name, glsl::kEncodeForDisplayLocation, encode ? 1 : 0);
        ShadowMap::bindForLookup(name, hasMap ? ctx.native(map) : 0u, lookup);
        world.draw(name);
    });
    if (hasMap) pass.read(map);
    pass.setTaps(2 + (hasMap ? shadowLookupTaps(lookup) : 0));  // base colour, emissive, the PCF taps
    if (options.declaresState) {
        PassState state = sceneDrawState(world.scene());
        if (options.viewport) state.viewport = *options.viewport;
        pass.setState(state);
    }
    runsWith(pass, program_);
    return pass;
}

Pass& LitScenePass::declareIntoWindow(FrameGraph& graph, const World& world, const DeclaredShadowMap& shadow,
                                      const LitSceneOptions& options) const {
    Pass& pass = addPass(graph, world, shadow, options);
    if (options.clears) {
        pass.writeColor(graph.output());
        pass.state().clearColor = windowClearColor(world.scene());
        pass.state().clearDepth = 1.0f;
    } else {
        pass.modify(graph.output(), TextureUsage::ColorAttachment);
    }
    return pass;
}

HdrSceneTargets LitScenePass::declareIntoTargets(FrameGraph& graph, const World& world,
                                                 const DeclaredShadowMap& shadow,
                                                 const LitSceneOptions& options,
                                                 const std::string& prefix) const {
    const Scene& scene = world.scene();
    Pass& pass = addPass(graph, world, shadow, options);
    HdrSceneTargets targets;
    targets.color = pass.create(prefix + ".color", {TextureSize::output(), TextureFormat::RGBA16F, 1},
                                TextureUsage::ColorAttachment);
    targets.depth = pass.create(prefix + ".depth", {TextureSize::output(), TextureFormat::Depth32F, 1},
                                TextureUsage::DepthAttachment);
    // A float target holds linear light: the sky is cleared to its linear value, or to the display
    // value when the shader encodes (then everything in the target is display-encoded alike).
    pass.state().clearColor =
        options.encodeForDisplay ? windowClearColor(scene) : hdrSceneState(scene).clearColor;
    pass.state().clearDepth = 1.0f;
    return targets;
}

}  // namespace lesson03
