#version 450 core
// Deliberately broken (step 2): reads a varying the vertex shader never writes, so linking fails.
layout(location = 7) in vec3 neverWritten;
out vec4 color;
void main() { color = vec4(neverWritten, 1.0); }
