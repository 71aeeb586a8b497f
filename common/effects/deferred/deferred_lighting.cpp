#include "effects/deferred/deferred_lighting.hpp"

#include <algorithm>
#include <string>

#include <glm/gtc/type_ptr.hpp>

#include "base/log.hpp"
#include "effects/deferred/deferred_bindings.hpp"
#include "effects/scene/hdr_scene_pass.hpp"

namespace fx {
namespace {

// Texture lookups of gbuffer_read.glsl for one pixel: albedo, depth, normal, and the stored position
// where the layout has one (compact rebuilds it from depth).
int gbufferTaps(const GBufferTargets& g) {
    return g.position ? 4 : 3;
}

}  // namespace

const FullscreenPass& DeferredLighting::pass(GBufferLayout layout, bool tiled) const {
    const int n = static_cast<int>(layout);
    std::optional<FullscreenPass>& slot = passes_[n * 2 + (tiled ? 1 : 0)];
    if (!slot) {
        std::string defines =
            cat("#define LAYOUT ", n, "\n#define SHININESS ", std::to_string(shininess_), "\n");
        if (tiled)
            defines += cat("#define TILED 1\n#define TILE_SIZE ", kTileSize, "\n#define MAX_TILE_LIGHTS ",
                           kMaxTileLights, "\n");
        slot.emplace("effects/deferred/deferred_lighting.frag",
                     cat("deferred lighting (", toString(layout), tiled ? ", tiled" : "", ")"), defines);
    }
    return *slot;
}

TextureHandle DeferredLighting::declare(FrameGraph& graph, const Scene& scene, const GBufferTargets& g,
                                        const PointLightBuffer& lights, const DeclaredShadowMap& shadow,
                                        const std::optional<CulledTiles>& tiles) const {
    const FullscreenPass* fullscreen = &pass(g.layout, tiles.has_value());
    const PointLightBuffer* buffer = &lights;
    const std::optional<CulledTiles> culled = tiles;
    Pass& pass = fullscreen->addPass(
        graph, "deferred lighting", [fullscreen, buffer, &scene, g, shadow, culled](PassContext& ctx) {
            GLuint program = fullscreen->program();
            CameraMatrices camera = offsetCameraMatrices(scene.camera, g.worldOffset, ctx.targetSize());
            SceneMeshes::setFrameUniforms(program, scene, camera);
            glm::mat4 inverse = glm::inverse(camera.viewProjection);
            glProgramUniformMatrix4fv(program, glsl::kInverseViewProjectionLocation, 1, GL_FALSE,
                                      glm::value_ptr(inverse));
            glProgramUniform1f(program, glsl::kHdrMaxLocation, kSceneHdrMax);
            auto sky = [](float c) { return std::clamp(c, 0.0f, kSceneHdrMax); };
            glProgramUniform3f(program, glsl::kSkyLocation, sky(scene.background.r), sky(scene.background.g),
                               sky(scene.background.b));
            glProgramUniform3fv(program, glsl::kWorldOffsetLocation, 1, glm::value_ptr(g.worldOffset));
            glProgramUniform1i(program, glsl::kPointLightCountLocation, buffer->count());
            buffer->bind();
            if (culled) {
                glProgramUniform1i(program, glsl::kTilesXLocation, culled->tilesX);
                glBindBufferBase(GL_SHADER_STORAGE_BUFFER, glsl::kTileLightsBinding, culled->listBuffer);
            }
            GLuint shadowTexture = shadow.pass && shadow.lookup.enabled ? ctx.native(shadow.map) : 0;
            ShadowMap::bindForLookup(program, shadowTexture, shadow.lookup);
            GLuint position = g.position ? ctx.native(*g.position) : 0;
            fullscreen->draw({ctx.native(g.albedo), ctx.native(g.normal), position, ctx.native(g.depth)});
        });
    pass.read(g.albedo).read(g.normal).read(g.depth);
    if (g.position) pass.read(*g.position);
    if (shadow.pass) pass.read(shadow.map);
    if (tiles) pass.read(tiles->heat);
    pass.setTaps(gbufferTaps(g) + (shadow.pass ? shadowLookupTaps(shadow.lookup) : 0));
    return pass.create("deferred.color", {TextureSize::output(), TextureFormat::RGBA16F, 1},
                       TextureUsage::ColorAttachment);
}

TextureHandle DeferredLighting::declarePositionError(FrameGraph& graph, const Scene& scene,
                                                     const GBufferTargets& g) const {
    const int n = static_cast<int>(g.layout);
    if (!errorPasses_[n])
        errorPasses_[n].emplace("effects/deferred/position_error.frag",
                                cat("position error (", toString(g.layout), ")"),
                                cat("#define LAYOUT ", n, "\n"));
    const FullscreenPass* error = &*errorPasses_[n];
    const TextureHandle reference = *g.referencePosition;
    Pass& pass = error->addPass(graph, "position error", [error, &scene, g, reference](PassContext& ctx) {
        CameraMatrices camera = offsetCameraMatrices(scene.camera, g.worldOffset, ctx.targetSize());
        glm::mat4 inverse = glm::inverse(camera.viewProjection);
        glProgramUniformMatrix4fv(error->program(), glsl::kInverseViewProjectionLocation, 1, GL_FALSE,
                                  glm::value_ptr(inverse));
        GLuint position = g.position ? ctx.native(*g.position) : 0;
        // The normal's unit stays empty: the shader never samples it, so the pass table does not say
        // it reads it (RenderDoc's capture of the pass would show no such read).
        error->draw({ctx.native(g.albedo), 0, position, ctx.native(g.depth), ctx.native(reference)});
    });
    pass.read(g.albedo).read(g.depth).read(reference);
    pass.setTaps(gbufferTaps(g));  // the normal is not read; the reference position is
    if (g.position) pass.read(*g.position);
    return pass.create("gbuffer.position_error", {TextureSize::output(), TextureFormat::RGBA16F, 1},
                       TextureUsage::ColorAttachment);
}

void DeferredLighting::declareViews(FrameGraph& graph, const Scene& scene, const GBufferTargets& g,
                                    float viewRange) const {
    const int n = static_cast<int>(g.layout);
    if (!viewPasses_[n])
        viewPasses_[n].emplace("effects/deferred/gbuffer_views.frag",
                               cat("gbuffer views (", toString(g.layout), ")"),
                               cat("#define LAYOUT ", n, "\n"));
    const FullscreenPass* views = &*viewPasses_[n];
    Pass& pass = views->addPass(graph, "gbuffer views", [views, &scene, g, viewRange](PassContext& ctx) {
        CameraMatrices camera = offsetCameraMatrices(scene.camera, g.worldOffset, ctx.targetSize());
        glm::mat4 inverse = glm::inverse(camera.viewProjection);
        GLuint program = views->program();
        glProgramUniformMatrix4fv(program, glsl::kInverseViewProjectionLocation, 1, GL_FALSE,
                                  glm::value_ptr(inverse));
        glProgramUniform3fv(program, glsl::kViewsEyeLocation, 1, glm::value_ptr(camera.position));
        glProgramUniform1f(program, glsl::kViewsRangeLocation, viewRange);
        GLuint position = g.position ? ctx.native(*g.position) : 0;
        views->draw({ctx.native(g.albedo), ctx.native(g.normal), position, ctx.native(g.depth)});
    });
    pass.read(g.albedo).read(g.normal).read(g.depth);
    if (g.position) pass.read(*g.position);
    pass.setTaps(gbufferTaps(g));
    const TextureDesc rgba8{TextureSize::output(), TextureFormat::RGBA8, 1};
    pass.create("gbuffer.view_normal", rgba8, TextureUsage::ColorAttachment);
    pass.create("gbuffer.view_depth", rgba8, TextureUsage::ColorAttachment);
}

}  // namespace fx
