#include "effects/shadow/shadow_lit_pass.hpp"

#include <algorithm>

#include <glm/geometric.hpp>

namespace fx {
namespace {

constexpr GLint kHdrMaxLocation = 30;  // shaders/effects/shadow/shadowed_scene.frag

// Everything once, then the skinned objects at each placement.
void drawWithPlacements(GLuint program, const Scene& scene, const SceneMeshes& meshes, double seconds,
                        const std::vector<glm::mat4>& placements) {
    MeshDrawOptions o;
    if (placements.empty()) {
        (void)meshes.draw(program, scene, seconds, o);
        return;
    }
    o.skinFilter = SkinFilter::withoutSkin;
    (void)meshes.draw(program, scene, seconds, o);
    o.skinFilter = SkinFilter::skinnedOnly;
    for (const glm::mat4& placement : placements) {
        o.placement = placement;
        (void)meshes.draw(program, scene, seconds, o);
    }
}

}  // namespace

ShadowLitPass ShadowLitPass::create() {
    ShadowLitPass pass;
    pass.program_ = gl::ReloadableProgram({"effects/shadow/shadowed_scene.vert",
                                           "effects/shadow/shadowed_scene.frag",
                                           {},
                                           {},
                                           "scene with shadows (linear HDR)"});
    return pass;
}

HdrSceneTargets ShadowLitPass::declare(FrameGraph& graph, const Scene& scene, const SceneMeshes& meshes,
                                       double seconds, const DeclaredShadowMap& shadow,
                                       const std::vector<glm::mat4>& skinnedPlacements) const {
    const gl::ReloadableProgram* program = &program_;
    ShadowLookup lookup = shadow.lookup;
    bool hasMap = shadow.pass != nullptr;
    TextureHandle map = shadow.map;
    Pass& pass = graph.addPass("scene", [=, &scene, &meshes](PassContext& ctx) {
        Size2D size = ctx.targetSize();
        CameraMatrices camera = cameraMatrices(scene.camera, size.width, size.height);
        GLuint name = program->name();
        SceneMeshes::setFrameUniforms(name, scene, camera);
        glProgramUniform1f(name, kHdrMaxLocation, kSceneHdrMax);
        ShadowMap::bindForLookup(name, hasMap ? ctx.native(map) : 0, lookup);
        drawWithPlacements(name, scene, meshes, seconds, skinnedPlacements);
    });
    if (hasMap) pass.read(map);
    HdrSceneTargets targets;
    targets.color = pass.create("scene.color", {TextureSize::output(), TextureFormat::RGBA16F, 1},
                                TextureUsage::ColorAttachment);
    targets.depth = pass.create("scene.depth", {TextureSize::output(), TextureFormat::Depth32F, 1},
                                TextureUsage::DepthAttachment);
    pass.setState(hdrSceneState(scene));
    if (!program_.usable()) pass.disable("the shadowed scene program did not build: " + program_.error());
    return targets;
}

TextureHandle ShadowLitPass::declareLightView(FrameGraph& graph, const Scene& scene,
                                              const SceneMeshes& meshes, double seconds,
                                              const DeclaredShadowMap& shadow,
                                              const std::vector<glm::mat4>& skinnedPlacements,
                                              int size) const {
    size = std::max(size, 1);
    const gl::ReloadableProgram* program = &program_;
    ShadowLookup lookup = shadow.lookup;
    bool hasMap = shadow.pass != nullptr;
    TextureHandle map = shadow.map;
    Pass& pass = graph.addPass("shadow light view", [=, &scene, &meshes](PassContext& ctx) {
        CameraMatrices camera;
        camera.view = lookup.light.view;
        camera.projection = lookup.light.projection;
        camera.viewProjection = lookup.light.viewProjection;
        camera.position = lookup.light.centre + lookup.light.directionToLight * lookup.light.farDistance;
        GLuint name = program->name();
        SceneMeshes::setFrameUniforms(name, scene, camera);
        glProgramUniform1f(name, kHdrMaxLocation, kSceneHdrMax);
        ShadowMap::bindForLookup(name, hasMap ? ctx.native(map) : 0, lookup);
        drawWithPlacements(name, scene, meshes, seconds, skinnedPlacements);
    });
    if (hasMap) pass.read(map);
    TextureHandle color =
        pass.create("shadow.light_view", {TextureSize::absolute(size, size), TextureFormat::RGBA16F, 1},
                    TextureUsage::ColorAttachment);
    pass.create("shadow.light_view_depth", {TextureSize::absolute(size, size), TextureFormat::Depth32F, 1},
                TextureUsage::DepthAttachment);
    PassState state = hdrSceneState(scene);
    state.faceCulling = false;  // seen from the light, a one-sided ground would vanish from below
    pass.setState(state);
    if (!hasMap) pass.notCalledFor("scene has no directional light that casts shadows");
    if (!program_.usable()) pass.disable("the shadowed scene program did not build: " + program_.error());
    return color;
}

}  // namespace fx
