// Where a lit scene program's inputs are: the uniform locations and the texture and buffer bindings
// every scene shader shares, written once. The shaders include this file and name them in their
// layout qualifiers; the C++ reads the same file (effects/scene/scene_bindings.hpp), so the two cannot
// disagree. Only `const int` lines belong here: they are GLSL and C++ alike.
// (The chapter's location map: 0 model, 2 view-projection.)
const int kModelLocation = 0;           // mat4
const int kViewProjectionLocation = 2;  // mat4: the camera's, or the light's in a shadow pass
const int kBaseColorLocation = 3;       // vec3
const int kEmissiveLocation = 4;        // vec3
const int kToLightLocation = 10;        // vec3, normalised
const int kLightColorLocation = 11;     // vec3: HDR colour times intensity
const int kAmbientLocation = 12;        // vec3
const int kCameraPositionLocation = 13;  // vec3
// The largest value a scene shader writes (kSceneHdrMax, effects/scene/hdr_scene_pass.hpp).
const int kHdrMaxLocation = 30;  // float
// The shadow lookup (shadow_lookup.glsl, set by ShadowMap::bindForLookup): locations 40 to 43 and
// texture unit 4 are the shadow's own.
const int kShadowMatrixLocation = 40;  // mat4: the light's view-projection
const int kShadowParamsLocation = 41;  // vec4: normal offset (m), depth bias, filter radius (texels), on
const int kShadowTapsLocation = 42;    // int
const int kShadowToLightLocation = 43;  // vec3
const int kShadowMapBinding = 4;        // sampler2D: the depth map
// The material's textures (effects/scene/material_textures.hpp).
const int kBaseColorTextureBinding = 0;  // sampler2D
const int kEmissiveTextureBinding = 1;   // sampler2D
// The joint matrices of the object being skinned (std430 storage buffer, skinning.glsl).
const int kJointMatricesBinding = 0;
