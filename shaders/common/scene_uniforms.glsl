// Uniforms every lit scene shader shares, at the explicit locations of effects/scene_meshes.hpp
// (the chapter's location map: 0 model, 2 view-projection).
layout(location = 0) uniform mat4 modelMatrix;
layout(location = 2) uniform mat4 viewProjectionMatrix;
layout(location = 3) uniform vec3 baseColor;
layout(location = 4) uniform vec3 emissiveColor;
layout(location = 10) uniform vec3 toLight;
layout(location = 11) uniform vec3 lightColor;
layout(location = 12) uniform vec3 ambientLight;
layout(location = 13) uniform vec3 cameraPosition;
