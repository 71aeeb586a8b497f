#pragma once
// Ray-marched clouds (the Clouds chapter): one full-screen pass "clouds" that blends a cloud layer
// over the scene's colour (src alpha, one minus src alpha), shaders/effects/clouds/clouds.frag.
//
//   CloudPass clouds;  // its programs build when a frame first asks for them
//   CloudDensityTexture density = CloudDensityTexture::load(layer.densityTexture.resolved);
//   Pass& pass = clouds.declare(graph, {hdr.color, hdr.depth, &shadowMap}, frameSettings);
//
// The pass modifies scene.color and reads scene.depth. The frame graph attaches only what a pass
// writes, so the framebuffer it draws into holds the colour texture alone: the depth texture it
// samples is not attached, which is the chapter's "colour-only FBO that shares the colour texture"
// and no feedback loop (the graph refuses a pass that samples what it renders into).
#include <cstdint>
#include <string>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "effects/clouds/cloud_march.hpp"
#include "effects/post/fullscreen_pass.hpp"
#include "effects/post/fullscreen_variants.hpp"
#include "effects/shadow/shadow_map.hpp"
#include "gl/texture.hpp"
#include "image/image.hpp"
#include "render/frame_graph.hpp"

namespace fx {

// What the shader does, one bit per idea (the same numbers as in clouds.frag).
enum CloudFeature : int {
    cloudRejectBehind = 1,         // plane: hits behind the eye rejected (off: the mirrored layer)
    cloudTwoScales = 2,            // a second layer of the texture at another scale
    cloudDepthAware = 4,           // the scene's depth limits the ray
    cloudEyeInside = 8,            // start at the eye inside the slab, stop at its faces (§2.1)
    cloudShadows = 16,             // object shadows from the shadow map (§2.3)
    cloudThreshold = 32,           // coverage threshold (§2.5)
    cloudHeightShaping = 64,       // thinner toward the top (§2.6)
    cloudDistanceOcclusion = 128,  // beyond: stop at the surface's distance along the ray
    cloudBeerLambert = 256,        // beyond: opacity from the step's length (converges with the count)
};

enum class CloudStage { screenTexture = 0, plane = 1, march = 2 };
enum class CloudDither { none = 0, bayer = 1, ign = 2, r2 = 3 };
const char* cloudDitherName(CloudDither dither);

// Everything one frame of the pass needs, in the scene's units.
struct CloudFrameSettings {
    CloudStage stage = CloudStage::march;
    int features = 0;  // CloudFeature bits
    CloudDither dither = CloudDither::none;
    int frameIndex = 0;
    CloudMarch march;          // slab, samples, threshold (cloud_march.hpp: every guard applied)
    float planeHeight = 1.0f;  // the plane of stage `plane`
    glm::vec2 scales{1.0f / 311.0f, 1.0f / 127.0f};  // texture repeats per metre
    glm::vec4 scrollOffset{0.0f};                    // CloudScroll::offset()
    glm::vec3 color{1.0f};
    // The camera exactly as the scene pass drew with it (cameraMatrices at the target's size).
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    glm::vec3 cameraPosition{0.0f};
    // Density lookups at the level of the pixel's footprint (a texture with mipmaps); false: level 0, the
    // chapter's texture (one level), which shimmers where a pixel covers many texels.
    bool mipmaps = false;
    // A deliberate mistake (lesson 08's depth_lookup_bug): a layer of its own smaller than the depth reads
    // the depth at its own pixel coordinates, as if the two had the same size.
    bool depthAtLayerPixels = false;
    // Set by CloudPass::declareLayer: premultiplied output, and scene depth texels per target pixel.
    bool premultiplied = false;
    int depthStride = 1;
};

// The texture offsets the shader gets: the scroll plus the camera's position in texture units,
// wrapped in double. The shader works with positions relative to the camera, so its numbers stay
// small however far the camera is from the origin.
glm::vec4 cloudShaderOffsets(const CloudFrameSettings& settings);

// Sets the camera's uniforms of a cloud shader (locations 0 to 3 of clouds.frag and cloud_shadow.frag:
// inverse projection, view-to-world rotation, camera position, texture offsets), with the same
// matrices that drew the scene; a projection without a finite inverse gets the identity.
void setCloudCameraUniforms(GLuint program, const CloudFrameSettings& settings);

// The shadow lookup the clouds use: the scene's, with fewer PCF taps (a lookup per sample) and no
// normal offset (clouds have no normal; the sample moves back along the view ray instead).
ShadowLookup cloudShadowLookup(const ShadowLookup& sceneLookup);
// The chapter's shadow offset: the world size of one texel of the shadow map, from the map's own
// size (the chapter's code reads the window's width by mistake).
inline float cloudShadowOffset(const ShadowLookup& lookup) {
    return lookup.light.texelWorldSize;
}

// The density texture, as the chapter stores it: SRGB8_ALPHA8 (so .r is sRGB-decoded when sampled),
// one level, linear filtering, GL_REPEAT (the UVs are unbounded). With `mipmaps`, every level, filtered
// between them (for CloudFrameSettings::mipmaps).
class CloudDensityTexture {
public:
    CloudDensityTexture() = default;
    static Result<CloudDensityTexture> load(const std::string& path, bool mipmaps = false);
    // From RGBA texels (rows bottom-up), e.g. a constant density for tests.
    static CloudDensityTexture fromImage(const ByteImage& rgba, bool mipmaps = false);
    GLuint name() const { return texture_.name(); }
    std::uint64_t bytes() const;
    explicit operator bool() const { return static_cast<bool>(texture_); }

private:
    gl::Texture texture_;
};

struct CloudInputs {
    TextureHandle color;                        // modified: the clouds blend over it
    TextureHandle depth;                        // read (not attached) when the settings ask for depth
    const DeclaredShadowMap* shadow = nullptr;  // read when the settings ask for shadows and it exists
};

class CloudPass {
public:
    // The program for these settings: the stage, the features that stage reads, the dither and the
    // premultiplied output are #defines (clouds.frag), one program per combination, built on first use.
    const FullscreenPass& programFor(const CloudFrameSettings& settings) const;

    // Declares "clouds". `density` must outlive the frame's execution. A settings.march that is not
    // drawn (no thickness, no samples) or a threshold that leaves no cloud still declares the pass:
    // it runs and writes nothing visible, so the hard cases are testable and the table stays stable.
    Pass& declare(FrameGraph& graph, const CloudInputs& inputs, const CloudDensityTexture& density,
                  const CloudFrameSettings& settings) const;

    // Declares "clouds march": the same march into a texture of its own (`textureName`, RGBA16F,
    // premultiplied colour) of `size` (the output's, or a fraction of it), for the temporal
    // accumulation and the half-resolution path (cloud_temporal.hpp). Nothing is blended.
    TextureHandle declareLayer(FrameGraph& graph, const CloudInputs& inputs,
                               const CloudDensityTexture& density, CloudFrameSettings settings, int divisor,
                               const std::string& textureName = "clouds.layer") const;

    // The state the pass declares: no depth, straight-alpha blending, no culling, every channel.
    static PassState state();

private:
    FullscreenVariants programs_{"effects/clouds/clouds.frag", "clouds"};
};

}  // namespace fx
