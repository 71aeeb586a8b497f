#version 450 core
// Lesson 08's sky_distance, a deliberate mistake: a sky drawn at a finite distance with depth writes on,
// as a skybox drawn like any other object is. The pass has no colour attachment and tests LESS against
// scene.depth, so it writes only where nothing was drawn (depth still 1): the sky is then a surface the
// clouds stop at.
#include "sky_depth_bindings.glsl"

layout(location = kSkyDepthLocation) uniform float skyDepth;

void main() {
    gl_FragDepth = skyDepth;
}
