#pragma once
// Cloud shadows on the ground (beyond the Clouds chapter), from the same density the clouds are
// marched through. Two full-screen passes, declared before the clouds are drawn over the scene:
//
//   "cloud shadow map"   reads scene.depth, creates "clouds.shadow" (R16F, the output's size): for each
//                        pixel, the surface rebuilt from depth, then the density marched from it toward
//                        the sun through the slab; the transmittance exp(-optical depth), 1 = no cloud.
//   "cloud shadow apply" modifies scene.color with the blend dst x src: colour x (1 - sunShare x (1 - T)).
//
//   CloudShadowPass cloudShadow;  // builds its programs: the context is current
//   cloudShadow.declare(graph, {hdr.color, hdr.depth}, density, cloudSettings, {toLight, 0.7f});
//
// The map pass samples the depth texture without attaching it (it writes only clouds.shadow), and the
// apply pass attaches scene.color alone: no feedback loop. The lit scene shader is not changed, so the
// lessons that share it draw what they drew.
#include <glm/vec3.hpp>

#include "effects/clouds/cloud_pass.hpp"
#include "effects/post/fullscreen_pass.hpp"
#include "render/frame_graph.hpp"

namespace fx {

// Samples along each shadow ray: the density is smooth over a few metres of slab, and the map is
// sampled without dither, so a few samples already give a steady picture.
inline constexpr int kCloudShadowSamples = 8;

struct CloudShadowSettings {
    glm::vec3 toLight{0.0f, 1.0f, 0.0f};  // toward the sun (any length; normalised here)
    float sunShare = 0.7f;                // the part of the ground's light a cloud can take away
    int samples = kCloudShadowSamples;
};

// The unit vector toward the sun from a directional light's travel direction (Light::direction):
// straight up when the direction has no length or is not finite.
glm::vec3 cloudShadowToLight(const glm::vec3& lightDirection);

struct CloudShadowInputs {
    TextureHandle color;  // modified by the apply pass
    TextureHandle depth;  // read by the map pass
};

class CloudShadowPass {
public:
    // Declares "cloud shadow map" alone and returns "clouds.shadow" (for tests and the inspector).
    TextureHandle declareMap(FrameGraph& graph, TextureHandle depth, const CloudDensityTexture& density,
                             const CloudFrameSettings& clouds, const CloudShadowSettings& shadow) const;
    // Declares both passes: the map, then the scene darkened by it. Returns the map.
    TextureHandle declare(FrameGraph& graph, const CloudShadowInputs& inputs,
                          const CloudDensityTexture& density, const CloudFrameSettings& clouds,
                          const CloudShadowSettings& shadow) const;

private:
    void setMapUniforms(const CloudFrameSettings& clouds, const CloudShadowSettings& shadow,
                        Size2D target) const;

    FullscreenPass map_{"effects/clouds/cloud_shadow.frag", "cloud shadow map"};
    FullscreenPass apply_{"effects/clouds/cloud_shadow_apply.frag", "cloud shadow apply"};
};

}  // namespace fx
