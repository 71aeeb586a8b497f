#pragma once
// The deferred lighting pass: one full-screen triangle that reads the G-buffer under each pixel,
// rebuilds its world position (from depth with the inverse of the very matrices the G-buffer pass drew
// with, or from the fat layouts' position target), and adds the scene's sun with its shadow map, the
// ambient light and every point light (or, after tiled culling, only the ones listed for the pixel's
// tile), into "deferred.color" (RGBA16F, clamped to [0, kSceneHdrMax], NaN to 0).
//
//   DeferredLighting lighting;  // its programs build when a frame first asks for them
//   TextureHandle lit = lighting.declare(graph, scene, g, lights, shadow, nullptr);
#include <optional>

#include "effects/deferred/gbuffer_pass.hpp"
#include "effects/deferred/point_light_buffer.hpp"
#include "effects/post/fullscreen_pass.hpp"
#include "effects/shadow/shadow_map.hpp"

namespace fx {

// What the tiled culling pass made for the lighting pass to read (tiled_culling.hpp).
struct CulledTiles {
    GLuint listBuffer = 0;  // per tile: the count, then up to kMaxTileLights indices
    int tilesX = 0;
    TextureHandle heat;  // "cull.heat", lights per tile; the lighting pass reads it to run after culling
};

inline constexpr int kTileSize = 16;
inline constexpr int kMaxTileLights = 255;
inline constexpr float kDefaultShininess = 40.0f;

class DeferredLighting {
public:
    // `shininess`: the point lights' specular exponent (40, the lecture's; the hard cases test 0 and
    // huge ones: pow(0, 0) is undefined in GLSL, so the shader takes an exponent of 0 as a flat 1).
    explicit DeferredLighting(float shininess = kDefaultShininess) : shininess_(shininess) {}

    // Declares "deferred lighting". `scene`, `lights` must outlive the frame's execution; `shadow` may
    // have no pass (no shadow-casting light): the sun then lights without shadow.
    TextureHandle declare(FrameGraph& graph, const Scene& scene, const GBufferTargets& g,
                          const PointLightBuffer& lights, const DeclaredShadowMap& shadow,
                          const std::optional<CulledTiles>& tiles) const;

    const FullscreenPass& pass(GBufferLayout layout, bool tiled) const;

    // "position error": |the layout's world position - g.referencePosition| per pixel as a log-scale
    // colour, the metres in alpha, into "gbuffer.position_error" (RGBA16F). `g` must have the reference.
    TextureHandle declarePositionError(FrameGraph& graph, const Scene& scene, const GBufferTargets& g) const;

    // "gbuffer views", for people: "gbuffer.view_normal" (the decoded normal as a colour) and
    // "gbuffer.view_depth" (linear distance, white near, black at `viewRange` m), both RGBA8. Nothing
    // reads them, so the pass runs only while the inspector or a capture asks for one.
    void declareViews(FrameGraph& graph, const Scene& scene, const GBufferTargets& g,
                      float viewRange = 40.0f) const;

private:
    float shininess_ = kDefaultShininess;
    mutable std::optional<FullscreenPass> passes_[8];
    mutable std::optional<FullscreenPass> viewPasses_[4];  // [layout * 2 + tiled], built when first used
    mutable std::optional<FullscreenPass> errorPasses_[4];
};

}  // namespace fx
