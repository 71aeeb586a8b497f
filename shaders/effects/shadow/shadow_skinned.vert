#version 450 core
// Depth-only shadow pass, skinned meshes (Shader effects §2: shadow_skeletal.vert): shadow_static.vert
// plus the skinning of the lit skeletal shader. The joint matrices come from the storage buffer at
// binding 0, which belongs to the context, so the object's buffer bound for this draw is the one read.
//
// The product: T*(J*p) is two mat4*vec4 (32 mul, 24 add); without the parentheses GLSL evaluates
// left to right, (T*J)*p, a mat4*mat4 and a mat4*vec4 (80 mul, 60 add). Same result, more work.
// GROUPED_PRODUCT selects the slow form for the lesson's comparison.
#include "../../common/skinning.glsl"

layout(location = kModelLocation) uniform mat4 modelMatrix;
layout(location = kViewProjectionLocation) uniform mat4 viewProjectionMatrix;

layout(location = 0) in vec3 position;
layout(location = 1) in vec2 texcoord;  // for the alpha cutoff (shadow_depth.frag)

layout(location = 1) out vec2 outTexcoord;
layout(location = 3) in uvec4 joints;
layout(location = 4) in vec4 weights;

void main() {
    outTexcoord = texcoord;
    mat4 J = skinMatrix(joints, weights);
    vec4 p = vec4(position, 1.0);
#ifdef GROUPED_PRODUCT
    vec4 world = modelMatrix * J * p;
#else
    vec4 world = modelMatrix * (J * p);
#endif
    gl_Position = viewProjectionMatrix * world;
    gl_Position.z = max(gl_Position.z, -gl_Position.w);  // pancaking, as in shadow_static.vert
}
