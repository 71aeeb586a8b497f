#version 450 core
// A plain full-screen copy: the unit of cost the bench compares every effect against.
layout(binding = 0) uniform sampler2D source;
layout(location = 1) in vec2 uv;
out vec4 color;
void main() { color = texture(source, uv); }
