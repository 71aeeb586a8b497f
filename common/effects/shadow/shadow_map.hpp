#pragma once
// A directional light's shadow map (Shader effects §2, and §3.3 for its state): a depth-only pass
// "shadow map" that draws the shadow casters from the light into "shadow.map" (Depth32F, mapSize
// squared), static meshes first with one program, then skinned meshes with a second program that
// skins in its vertex shader (joint matrices from the storage buffer at binding 0): one switch.
//
//   ShadowMap shadows;  // builds its programs: the context is current
//   DeclaredShadowMap map = shadows.declare(graph, frame.world, settings, {});
//   // in a receiving pass that read(map.map):
//   ShadowMap::bindForLookup(program, ctx.native(map.map), map.lookup);
//   // and its fragment shader includes shaders/common/shadow_lookup.glsl:
//   //   float shadowVisibility(vec3 worldPosition, vec3 worldNormal);   // 1 lit, 0 shadowed
//
// Lookup contract (shaders/common/shadow_lookup.glsl): uniforms at locations 40 (light
// view-projection, mat4), 41 (vec4: normal offset in metres, depth bias, filter radius in texels,
// 1 = on), 42 (int taps), 43 (vec3 direction to the light); the map as a plain sampler2D on texture
// unit 4, read with texelFetch and compared in the shader (no sampler object, no compare mode).
#include <cstdint>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "effects/post/fullscreen_pass.hpp"
#include "effects/scene/world.hpp"
#include "gl/program.hpp"
#include "render/frame_graph.hpp"
#include "scene/light_frustum.hpp"
#include "scene/scene.hpp"

namespace fx {

// The largest filter the lookup shader takes (kShadowMaxTaps there).
inline constexpr int kShadowMaxFilterTaps = 64;

// How the skinning product is written in the skinned shadow program (Shader effects chapter, §2).
enum class SkinningProduct {
    parenthesised,  // T*(J*p): two mat4*vec4, 32 mul + 24 add a vertex
    grouped,        // T*J*p = (T*J)*p: mat4*mat4 then mat4*vec4, 80 mul + 60 add a vertex
};
// Which shadow programs get the alpha cutoff (Shader effects chapter, §2: a uniform belongs to one
// program; the chapter sets it on the static shadow program at start-up and must set it again on the
// skinned one it adds).
enum class CutoffUniform {
    everyProgram,      // both programs discard below kAlphaCutoff: the fix
    firstProgramOnly,  // only the static program: the skinned one keeps GL's initial 0 and discards
                       // nothing, so skinned cut-out casters throw solid shadows (the chapter's bug)
};
// The alpha below which a cut-out texel casts no shadow (the chapter's 0.5; shadowed_scene.frag too).
inline constexpr float kAlphaCutoff = 0.5f;

struct OperationCount {
    int mul = 0;
    int add = 0;
};
OperationCount operationCount(SkinningProduct product);

// Whether the skinned draw uploads material uniforms (Shader effects chapter, §2.4: the error flood).
enum class MaterialUpload {
    askProgram,  // only when the program has them (Program::hasUniform, looked up once at link): the fix
    always,      // as the lit path does: GL_INVALID_OPERATION every draw on the shadow program (the
                 // chapter's error flood). The errors are counted as expected (gl::ExpectedErrorScope).
};

// What one execution of the pass did, for the overlay and the report.
struct ShadowPassStats {
    std::size_t staticDraws = 0;
    std::size_t skinnedDraws = 0;
    int programSwitches = 0;          // glUseProgram changes from one shadow program to the other
    std::int64_t glErrors = 0;        // errors raised by the pass (expected ones: MaterialUpload::always)
    std::size_t skinnedVertices = 0;  // vertices the skinned program transformed
};

struct ShadowPassOptions {
    bool drawStatic = true;
    bool drawSkinned = true;  // false: the chapter before section 2, the character casts no shadow
    // false: the pass declares no depth test, depth write, depth function or blend state and runs with
    // whatever the pass before it left (Shader effects §3.3: with the depth test off nothing is
    // written and every shadow vanishes). true: it declares all of them itself.
    bool setsItsOwnState = true;
    SkinningProduct product = SkinningProduct::parenthesised;
    MaterialUpload materialUpload = MaterialUpload::askProgram;
    CutoffUniform cutoff = CutoffUniform::everyProgram;
    // World transforms each skinned object is drawn at, on top of its own (a crowd); empty: once, as is.
    std::vector<glm::mat4> skinnedPlacements;
    // The lookup's PCF radius in metres, the same at every map size (0: 1.5 texels of the map).
    float filterRadiusMetres = 0.0f;
    std::string passName = "shadow map";
    std::string textureName = "shadow.map";
    // Filled in when the pass runs (must outlive the frame's execution); may be null.
    ShadowPassStats* stats = nullptr;
};

// What a receiving shader needs: the light, and the lookup's settings in the units the shader uses.
struct ShadowLookup {
    LightView light;
    float normalOffsetMetres = 0.0f;  // settings.normalOffset texels of this map
    float depthBias = 0.0f;
    float filterRadiusTexels = 1.5f;
    int filterTaps = 16;
    bool enabled = false;  // false: shadowVisibility() returns 1 everywhere
};

// The lookup for `settings` and `light`. The filter's radius is given in metres so that maps of
// different sizes blur the same width (a quality comparison needs the same picture at every size);
// filterRadiusMetres <= 0 means 1.5 texels of this map.
ShadowLookup shadowLookup(const ShadowSettings& settings, const LightView& light,
                          float filterRadiusMetres = 0.0f);
// Texture lookups of shadow_lookup.glsl's shadowVisibility per shaded pixel: the PCF taps, none when off
// (a pass's taps, render/pass_traffic.hpp).
int shadowLookupTaps(const ShadowLookup& lookup);

struct DeclaredShadowMap {
    Pass* pass = nullptr;     // null when the scene has no shadow-casting light
    TextureHandle map;        // "shadow.map", Depth32F
    ShadowSettings settings;  // as used: map size and taps in range
    ShadowLookup lookup;      // enabled only when the pass exists and is switched on
};

// The first directional light that casts shadows, or null.
const Light* shadowCastingLight(const Scene& scene);

// World-space bounds of the scene's objects at the world's time (glTF objects in their posed hierarchy,
// padded for skinned limbs), with each skinned object also at every one of `skinnedPlacements`:
// the shadow casters alone, and everything (casters and receivers).
struct ShadowBounds {
    Bounds casters;
    Bounds everything;
};
ShadowBounds sceneBounds(const World& world, const std::vector<glm::mat4>& skinnedPlacements = {});

class ShadowMap {
public:
    // Declares the shadow pass. `settings` comes from the light's shadow block (a lesson may override
    // mapSize and filterTaps: mapSize is clamped to [1, 8192], filterTaps to [1, 64]). The light view
    // is fitted to the scene (fitLightFrustum: across the light to the casters, along it to everything).
    // `options.stats` must outlive the frame's execution. When the scene has no
    // shadow-casting light, nothing is declared and the lookup comes back disabled.
    DeclaredShadowMap declare(FrameGraph& graph, const World& world, const ShadowSettings& settings,
                              const ShadowPassOptions& options) const;
    // The same with a light view the caller fitted.
    DeclaredShadowMap declare(FrameGraph& graph, const World& world, const ShadowSettings& settings,
                              const LightView& light, const ShadowPassOptions& options) const;

    // For the inspector: "shadow.depth_metres" (R32F, `size` squared), the map as metres from the
    // light's near plane (-1 where nothing was drawn). Runs only when someone inspects it.
    TextureHandle declareDepthView(FrameGraph& graph, const DeclaredShadowMap& map, int size = 512) const;

    // Sets the uniforms shadow_lookup.glsl reads on `program` and binds `depthTexture` to unit 4.
    // A disabled lookup (or texture 0) switches shadows off in the shader instead.
    static void bindForLookup(GLuint program, GLuint depthTexture, const ShadowLookup& lookup);

    // Vertices of the scene's skinned meshes (one placement), for the operation counts.
    static std::size_t skinnedVertexCount(const SceneMeshes& meshes);

    const gl::Program& skinnedProgram(SkinningProduct product) const;

private:
    const gl::ReloadableProgram& skinnedReloadable(SkinningProduct product) const;

    gl::ReloadableProgram static_{
        {"effects/shadow/shadow_static.vert", "effects/shadow/shadow_depth.frag", {}, {}, "shadow (static)"}};
    gl::ReloadableProgram skinned_{{"effects/shadow/shadow_skinned.vert",
                                    "effects/shadow/shadow_depth.frag",
                                    {},
                                    {},
                                    "shadow (skinned, T*(J*p))"}};
    gl::ReloadableProgram skinnedGrouped_{{"effects/shadow/shadow_skinned.vert",
                                           "effects/shadow/shadow_depth.frag",
                                           {},
                                           "#define GROUPED_PRODUCT\n",
                                           "shadow (skinned, (T*J)*p)"}};
    FullscreenPass depthView_{"effects/shadow/shadow_depth_view.frag", "shadow depth view"};
};

}  // namespace fx
