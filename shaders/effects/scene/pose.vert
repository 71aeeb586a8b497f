#version 450 core
// GPU skinning into a buffer (transform feedback): each vertex of the bind pose, blended by its joint
// matrices, is written out as position, texcoord, normal (32 bytes, the layout of a GpuMesh vertex).
// Nothing is rasterised; the posed buffer is then drawn by any program like a static mesh.
#include "../../common/skinning.glsl"

layout(location = 0) in vec3 position;
layout(location = 1) in vec2 texcoord;
layout(location = 2) in vec3 normal;
layout(location = 3) in uvec4 joints;
layout(location = 4) in vec4 weights;

layout(xfb_buffer = 0, xfb_offset = 0, xfb_stride = 32) out vec3 posedPosition;
layout(xfb_buffer = 0, xfb_offset = 12) out vec2 posedTexcoord;
layout(xfb_buffer = 0, xfb_offset = 20) out vec3 posedNormal;

void main() {
    mat4 skin = skinMatrix(joints, weights);
    vec4 p = skin * vec4(position, 1.0);
    posedPosition = p.xyz;
    posedTexcoord = texcoord;
    posedNormal = skinNormal(skin, normal);
    gl_Position = p;
}
