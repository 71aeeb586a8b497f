// The deferred passes' uniform locations and buffer bindings, written once for the shaders and the
// C++ (effects/deferred/deferred_bindings.hpp). The lit passes also have scene_bindings.glsl's scene
// uniforms (0 to 13), hdrMax (30) and shadow lookup (40 to 43), so theirs start at 20.
const int kPointLightCountLocation = 20;       // int: point_lights.glsl
const int kInverseViewProjectionLocation = 21;  // mat4: gbuffer_read.glsl
const int kSkyLocation = 23;                    // vec3: deferred_lighting.frag
const int kTilesXLocation = 24;                 // int: deferred_lighting.frag, tiled
const int kWorldOffsetLocation = 25;            // vec3: deferred_lighting.frag
const int kClipPlaneLocation = 26;              // vec4: mirrored_scene.vert
const int kObjectMirrorLocation = 32;           // mat4 (32 to 35): mirrored_scene.vert
const int kMirrorStrengthLocation = 27;         // float: mirror_surface.frag
const int kMirrorOutputSizeLocation = 28;       // vec2: mirror_surface.frag
const int kMirrorBlurSigmaLocation = 44;        // float: mirror_surface.frag (0: one sharp tap)
const int kMirrorBlurOffsetsLocation = 48;      // vec2[16] (48 to 63): mirror_surface.frag
const int kMirrorReflectionBinding = 0;         // sampler2D: mirror_surface.frag
const int kMirrorSceneDepthBinding = 1;         // sampler2D: mirror_surface.frag
// tiled_culling.comp (a program of its own)
const int kCullViewLocation = 30;               // mat4
const int kCullInverseProjectionLocation = 31;  // mat4
const int kCullDepthBinding = 3;                // sampler2D: the G-buffer's depth
const int kCullHeatBinding = 0;                 // r32f image: lights per tile
// The storage buffers (std430) the point lights and the tiles' lists are in.
const int kPointLightsBinding = 5;
const int kTileLightsBinding = 6;
// mrt_composite.frag
const int kMrtSkyLocation = 0;  // vec3
// heat_map.frag
const int kHeatMaxLightsLocation = 0;  // float
const int kHeatTileSizeLocation = 1;   // int
const int kHeatCapacityLocation = 2;   // float
// gbuffer_views.frag
const int kViewsEyeLocation = 0;    // vec3
const int kViewsRangeLocation = 1;  // float
