#version 450 core
// Deliberately broken (step 2): an error inside an included file's user, to show the line mapping.
#include "../../common/scene_uniforms.glsl"
out vec4 color;
void main() {
    color = vec4(baseColor * brightnes, 1.0);
}
