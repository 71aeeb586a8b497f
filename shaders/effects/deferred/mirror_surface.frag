#version 450 core
// The mirror's surface over the lit picture: the reflection under this pixel, blended in at the
// mirror's strength (alpha). The reflection was drawn with the same projection, so the pixel's own
// place in the output, as a fraction, is where its reflection is, whatever the reflection's size.
// The homework's optional blur averages 16 taps around that place, each offset blurSigma times a
// standard-normal sample (the chapter's: blurSigma 0.005 of the texture); blurSigma 0 takes one tap.
#include "deferred_bindings.glsl"

layout(binding = kMirrorReflectionBinding) uniform sampler2D reflection;
layout(binding = kMirrorSceneDepthBinding) uniform sampler2D sceneDepth;  // the G-buffer's: what is in front of the mirror
layout(location = kMirrorStrengthLocation) uniform float strength;
layout(location = kMirrorOutputSizeLocation) uniform vec2 outputSize;
layout(location = kMirrorBlurSigmaLocation) uniform float blurSigma;
layout(location = kMirrorBlurOffsetsLocation) uniform vec2 blurOffsets[16];
layout(location = 0) out vec4 color;

void main() {
    // The depth test by hand: the same vertex shader and matrices drew the plane into the G-buffer, so
    // its own depth matches to rounding; anything in front of it is nearer by far more than 1e-6.
    if (gl_FragCoord.z > texelFetch(sceneDepth, ivec2(gl_FragCoord.xy), 0).r + 1e-6) discard;
    vec2 uv = gl_FragCoord.xy / max(outputSize, vec2(1.0));
    vec3 reflected = texture(reflection, uv).rgb;
    if (blurSigma > 0.0) {
        reflected = vec3(0.0);
        for (int i = 0; i < 16; ++i) reflected += texture(reflection, uv + blurSigma * blurOffsets[i]).rgb;
        reflected /= 16.0;
    }
    color = vec4(reflected, clamp(strength, 0.0, 1.0));
}
