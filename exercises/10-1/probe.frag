#version 450 core
// The check of exercise 10-1: every pixel has its own mirror (a random unit normal, d from -5 to 5) and
// its own point within 10 m of the origin; it writes the point's mirror image (xyz) and its clip
// distance (w). The first pixels use the lesson's pond: the plane y = 0.02 facing up.
#include "mirror.glsl"
#include "../probe_inputs.glsl"

layout(location = 0) out vec4 result;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec4 plane = vec4(probeDirection(pixel, 0u), 10.0 * probeRandom(pixel, 3u) - 5.0);
    if (pixel.y == 0 && pixel.x < 4) plane = vec4(0.0, 1.0, 0.0, -0.02);
    vec3 p = 20.0 * vec3(probeRandom(pixel, 4u), probeRandom(pixel, 5u), probeRandom(pixel, 6u)) - 10.0;
    vec4 image = reflectionMatrix(plane) * vec4(p, 1.0);
    vec4 clip = reflectionClipPlane(plane);
    result = vec4(image.xyz / image.w, dot(clip.xyz, p) + clip.w);
}
