#version 450 core
#include "/proc/self/environ"
void main() {}
