#version 450 core
// Step 5: edit this file while the lesson runs; it reloads on save (or F5). Try changing the
// constant below, then break the syntax and watch the last good program keep running.
#include "../../common/scene_uniforms.glsl"
#include "../../common/lighting.glsl"
#include "../../common/output_transform.glsl"
layout(location = 2) in vec3 worldNormal;
out vec4 color;
const float kBrightness = 1.0;
void main() {
    vec3 linear = diffuseLighting(worldNormal, baseColor) * kBrightness + emissiveColor;
    color = vec4(linearToSrgb(linear), 1.0);
}
