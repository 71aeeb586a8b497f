// Uniforms every lit scene shader shares, at the locations of scene_bindings.glsl (which the C++
// reads too: SceneMeshes sets them).
#include "common/scene_bindings.glsl"

layout(location = kModelLocation) uniform mat4 modelMatrix;
layout(location = kViewProjectionLocation) uniform mat4 viewProjectionMatrix;
layout(location = kBaseColorLocation) uniform vec3 baseColor;
layout(location = kEmissiveLocation) uniform vec3 emissiveColor;
layout(location = kToLightLocation) uniform vec3 toLight;
layout(location = kLightColorLocation) uniform vec3 lightColor;
layout(location = kAmbientLocation) uniform vec3 ambientLight;
layout(location = kCameraPositionLocation) uniform vec3 cameraPosition;
