#version 450 core
#include "out.glsl"
void main() {}
