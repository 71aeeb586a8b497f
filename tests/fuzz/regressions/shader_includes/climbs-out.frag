#version 450 core
#include "../secret.glsl"
void main() {}
