#version 450 core
#include "helper.glsl"
#include "effects/post/post_bindings.glsl"
void main() {}
