#version 450 core
// The depth texture as grey: what a plain sampler2D reads from it (lesson 09 step 1, shown_target).
layout(binding = 0) uniform sampler2D depth;
layout(location = 1) in vec2 uv;
out vec4 color;
void main() { color = vec4(vec3(texture(depth, uv).r), 1.0); }
