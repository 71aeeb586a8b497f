#version 450 core
// Deliberately broken (step 2): a missing semicolon.
out vec4 color;
void main() {
    color = vec4(1.0, 0.0, 1.0, 1.0)
}
