#pragma once
// Tiled light culling (the best engines' answer to a thousand lights, docs/chapters.md): a compute
// pass "light culling" splits the screen into 16 x 16 pixel tiles and lists, per tile, the point lights
// whose sphere reaches the tile's slice of the view frustum (between the nearest and the farthest
// surface in it). The lighting pass then evaluates only those. "cull.heat" (R32F, one texel per tile)
// holds how many lights touch each tile: the heat map's data (declareHeatMap draws it).
//
// Culling costs a pass of its own: with a handful of lights it is slower than evaluating them all, so
// it needs the scene feature manyLights (more than kManyLightsAbove lights) and is not called for
// otherwise; the pass table says why.
#include "base/log.hpp"
#include "effects/deferred/deferred_lighting.hpp"
#include "effects/scene/scene_work.hpp"
#include "gl/program.hpp"

namespace fx {

// Tiles across and down for an output of `size` (a partial tile at the edges counts; at least 1 each).
Size2D tileCount(Size2D size);

class TiledCulling {
public:
    // Declares "light culling": reads `g.depth`, writes "cull.heat" and the tile list buffer. It needs
    // SceneFeature::manyLights; lastPass() is it, for the lesson to ask whether it will run.
    CulledTiles declare(FrameGraph& graph, const Scene& scene, const GBufferTargets& g,
                        const PointLightBuffer& lights) const;
    Pass* lastPass() const { return lastPass_; }

    // "cull heat map": the lights per tile over `lit`, into "cull.heatmap" (RGBA16F).
    TextureHandle declareHeatMap(FrameGraph& graph, const CulledTiles& tiles, TextureHandle lit,
                                 int maxLights) const;

private:
    gl::ReloadableProgram program_{
        {{},
         {},
         "effects/deferred/tiled_culling.comp",
         cat("#define TILE_SIZE ", kTileSize, "\n#define MAX_TILE_LIGHTS ", kMaxTileLights, "\n"),
         "light culling (tiles)"}};
    FullscreenPass heatMap_{"effects/deferred/heat_map.frag", "cull heat map"};
    gl::BufferName list_ = gl::createBuffer("cull.tile_lights");
    mutable std::size_t listBytes_ = 0;
    mutable Pass* lastPass_ = nullptr;
};

}  // namespace fx
