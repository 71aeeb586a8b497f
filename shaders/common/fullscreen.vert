#version 450 core
// One triangle that covers the screen; no vertex buffer needed (gl_VertexID 0, 1, 2).
layout(location = 1) out vec2 uv;
void main() {
    vec2 corner = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
    uv = corner;
    gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
