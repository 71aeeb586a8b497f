#include "effects/deferred/tiled_culling.hpp"

#include <glm/gtc/type_ptr.hpp>

#include "base/log.hpp"
#include "effects/deferred/deferred_bindings.hpp"
#include "render_gl/program_pass.hpp"

namespace fx {

Size2D tileCount(Size2D size) {
    return {std::max(1, (size.width + kTileSize - 1) / kTileSize),
            std::max(1, (size.height + kTileSize - 1) / kTileSize)};
}

CulledTiles TiledCulling::declare(FrameGraph& graph, const Scene& scene, const GBufferTargets& g,
                                  const PointLightBuffer& lights) const {
    Size2D tiles = tileCount(graph.outputSize());
    CulledTiles out;
    out.listBuffer = list_.name();
    out.tilesX = tiles.width;
    out.heat = graph.declareTexture(
        "cull.heat", {TextureSize::absolute(tiles.width, tiles.height), TextureFormat::R32F, 1});
    const TiledCulling* self = this;
    const PointLightBuffer* buffer = &lights;
    Pass& pass = graph.addPass("light culling", [self, buffer, &scene, g, out](PassContext& ctx) {
        Size2D size = ctx.texture(g.depth).spec.size();
        Size2D n = tileCount(size);
        std::size_t bytes = std::size_t(n.width) * std::size_t(n.height) * (kMaxTileLights + 1) * 4;
        if (bytes > self->listBytes_) {
            glNamedBufferData(self->list_.name(), GLsizeiptr(bytes), nullptr, GL_DYNAMIC_DRAW);
            self->listBytes_ = bytes;
        }
        CameraMatrices camera = offsetCameraMatrices(scene.camera, g.worldOffset, size);
        GLuint program = self->program_.name();
        glProgramUniformMatrix4fv(program, glsl::kCullViewLocation, 1, GL_FALSE, glm::value_ptr(camera.view));
        glm::mat4 inverseProjection = glm::inverse(camera.projection);
        glProgramUniformMatrix4fv(program, glsl::kCullInverseProjectionLocation, 1, GL_FALSE,
                                  glm::value_ptr(inverseProjection));
        glProgramUniform1i(program, glsl::kPointLightCountLocation, buffer->count());
        buffer->bind();
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, glsl::kTileLightsBinding, self->list_.name());
        glBindTextureUnit(glsl::kCullDepthBinding, ctx.native(g.depth));
        glBindImageTexture(glsl::kCullHeatBinding, ctx.native(out.heat), 0, GL_FALSE, 0, GL_WRITE_ONLY,
                           GL_R32F);
        glUseProgram(program);
        glDispatchCompute(GLuint(n.width), GLuint(n.height), 1);
        // The lighting pass reads the list as a storage buffer and the heat map as a texture.
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    });
    pass.read(g.depth).writeStorage(out.heat).setTaps(kTileSize *
                                                      kTileSize);  // a tile's depths per heat texel
    needs(pass, SceneFeature::manyLights);
    lastPass_ = &pass;
    runsWith(pass, program_);
    return out;
}

TextureHandle TiledCulling::declareHeatMap(FrameGraph& graph, const CulledTiles& tiles, TextureHandle lit,
                                           int maxLights) const {
    const FullscreenPass* heat = &heatMap_;
    Pass& pass = heatMap_.addPass(graph, "cull heat map", [heat, tiles, lit, maxLights](PassContext& ctx) {
        glProgramUniform1f(heat->program(), glsl::kHeatMaxLightsLocation, float(std::max(maxLights, 1)));
        glProgramUniform1i(heat->program(), glsl::kHeatTileSizeLocation, kTileSize);
        glProgramUniform1f(heat->program(), glsl::kHeatCapacityLocation, float(kMaxTileLights));
        heat->draw({ctx.native(tiles.heat), ctx.native(lit)});
    });
    pass.read(tiles.heat).read(lit).setTaps(2);
    return pass.create("cull.heatmap", {TextureSize::output(), TextureFormat::RGBA16F, 1},
                       TextureUsage::ColorAttachment);
}

}  // namespace fx
