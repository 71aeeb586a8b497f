#include "effects/shadow/shadow_lit_pass.hpp"

#include <algorithm>

#include <glm/geometric.hpp>

#include "effects/shadow/shadow_bindings.hpp"
#include "render_gl/program_pass.hpp"

namespace fx {
namespace {

// Everything once, then the skinned objects at each placement.
void drawWithPlacements(GLuint program, const World& world, const std::vector<glm::mat4>& placements) {
    MeshDrawOptions o;
    if (placements.empty()) {
        (void)world.draw(program, o);
        return;
    }
    o.skinFilter = SkinFilter::withoutSkin;
    (void)world.draw(program, o);
    o.skinFilter = SkinFilter::skinnedOnly;
    for (const glm::mat4& placement : placements) {
        o.placement = placement;
        (void)world.draw(program, o);
    }
}

// The lit scene seen by `camera`, receiving the shadow map (`map` 0: none), skinned objects at each
// placement: the body of both the scene pass and the light's view.
void drawShadowed(GLuint program, const World& world, const CameraMatrices& camera, GLuint map,
                  const ShadowLookup& lookup, const std::vector<glm::mat4>& placements,
                  bool encodeForDisplay = false) {
    SceneMeshes::setFrameUniforms(program, world.scene(), camera);
    glProgramUniform1f(program, glsl::kHdrMaxLocation, kSceneHdrMax);
    glProgramUniform1i(program, glsl::kEncodeForDisplayLocation, encodeForDisplay ? 1 : 0);
    ShadowMap::bindForLookup(program, map, lookup);
    drawWithPlacements(program, world, placements);
}

// Texture lookups per shaded pixel of shadowed_scene.frag: base colour, emissive, and the PCF taps.
int shadowedSceneTaps(const ShadowLookup& lookup, bool hasMap) {
    return 2 + (hasMap ? shadowLookupTaps(lookup) : 0);
}

}  // namespace

Pass& ShadowLitPass::declareDraw(FrameGraph& graph, const World& world, const DeclaredShadowMap& shadow,
                                 const ShadowLitOptions& options) const {
    const gl::ReloadableProgram* program = &program_;
    ShadowLookup lookup = shadow.lookup;
    // The lookup's uniforms need the map's GL name, which exists only while the frame runs.
    bool hasMap = shadow.pass != nullptr;
    TextureHandle map = shadow.map;
    std::vector<glm::mat4> placements = options.skinnedPlacements;
    bool encode = options.encodeForDisplay;
    Pass& pass = graph.addPass(options.passName, [=](PassContext& ctx) {
        Size2D size = ctx.targetSize();
        CameraMatrices camera = cameraMatrices(world.scene().camera, size.width, size.height);
        drawShadowed(program->name(), world, camera, hasMap ? ctx.native(map) : 0, lookup, placements,
                     encode);
    });
    if (hasMap) pass.read(map);
    runsWith(pass.setTaps(shadowedSceneTaps(lookup, hasMap)), program_);
    return pass;
}

HdrSceneTargets ShadowLitPass::declare(FrameGraph& graph, const World& world, const DeclaredShadowMap& shadow,
                                       const std::vector<glm::mat4>& skinnedPlacements) const {
    ShadowLitOptions options;
    options.skinnedPlacements = skinnedPlacements;
    return declare(graph, world, shadow, options);
}

HdrSceneTargets ShadowLitPass::declare(FrameGraph& graph, const World& world, const DeclaredShadowMap& shadow,
                                       const ShadowLitOptions& options) const {
    Pass& pass = declareDraw(graph, world, shadow, options);
    HdrSceneTargets targets;
    targets.color = pass.create(options.prefix + ".color", {TextureSize::output(), TextureFormat::RGBA16F, 1},
                                TextureUsage::ColorAttachment);
    targets.depth =
        pass.create(options.prefix + ".depth", {TextureSize::output(), TextureFormat::Depth32F, 1},
                    TextureUsage::DepthAttachment);
    PassState state = hdrSceneState(world.scene());
    if (options.encodeForDisplay) state.clearColor = displayClearColor(world.scene());
    if (options.viewport) state.viewport = *options.viewport;
    pass.setState(state);
    return targets;
}

TextureHandle ShadowLitPass::declareLightView(FrameGraph& graph, const World& world,
                                              const DeclaredShadowMap& shadow,
                                              const std::vector<glm::mat4>& skinnedPlacements,
                                              int size) const {
    size = std::max(size, 1);
    const gl::ReloadableProgram* program = &program_;
    ShadowLookup lookup = shadow.lookup;
    bool hasMap = shadow.pass != nullptr;
    TextureHandle map = shadow.map;
    Pass& pass = graph.addPass("shadow light view", [=](PassContext& ctx) {
        CameraMatrices camera;
        camera.view = lookup.light.view;
        camera.projection = lookup.light.projection;
        camera.viewProjection = lookup.light.viewProjection;
        camera.position = lookup.light.centre + lookup.light.directionToLight * lookup.light.farDistance;
        drawShadowed(program->name(), world, camera, hasMap ? ctx.native(map) : 0, lookup, skinnedPlacements);
    });
    if (hasMap) pass.read(map);
    TextureHandle color =
        pass.create("shadow.light_view", {TextureSize::absolute(size, size), TextureFormat::RGBA16F, 1},
                    TextureUsage::ColorAttachment);
    pass.create("shadow.light_view_depth", {TextureSize::absolute(size, size), TextureFormat::Depth32F, 1},
                TextureUsage::DepthAttachment);
    PassState state = hdrSceneState(world.scene());
    state.faceCulling = false;  // seen from the light, a one-sided ground would vanish from below
    pass.setState(state).setTaps(shadowedSceneTaps(lookup, hasMap));
    if (!hasMap) pass.notCalledFor("scene has no directional light that casts shadows");
    runsWith(pass, program_);
    return color;
}

}  // namespace fx
