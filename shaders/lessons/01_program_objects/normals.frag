#version 450 core
// A debugging program: the world normal as a colour.
layout(location = 2) in vec3 worldNormal;
out vec4 color;
void main() {
    float len = length(worldNormal);
    vec3 n = len > 1e-6 ? worldNormal / len : vec3(0.0);
    color = vec4(n * 0.5 + 0.5, 1.0);
}
