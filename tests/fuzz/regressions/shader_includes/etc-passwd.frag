#version 450 core
#include "/etc/passwd"
void main() {}
