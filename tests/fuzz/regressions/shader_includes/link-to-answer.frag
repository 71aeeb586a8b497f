#version 450 core
#include "answer.glsl"
void main() {}
