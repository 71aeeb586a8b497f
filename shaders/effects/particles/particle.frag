#version 450 core
// The particle's colour. Only the sprite's alpha shapes it (the chapter's black base colour plus
// emission). Two blends:
//   straight alpha (steps 1 to 4): out = (emission, alpha), blended SRC_ALPHA, ONE_MINUS_SRC_ALPHA;
//   premultiplied (step 5): out = (emission * a, a * coverage), blended ONE, ONE_MINUS_SRC_ALPHA, so
//   fire (coverage 0: adds light) and smoke (coverage 1: covers) share one blend state and one draw.
// The emission is clamped to hdrMax (docs/numbers.md) and, with the soft fade on, the particle fades
// out where it nears the scene's surface (depth read as a texture, linearised first).
layout(location = 0) in vec2 corner;
layout(location = 1) in vec4 color;
layout(location = 2) flat in vec3 emitterFlags;  // coverage, textured, the chapter's unclamped alpha
layout(location = 3) in float viewDistance;

layout(binding = 0) uniform sampler2D sprite;
layout(binding = 1) uniform sampler2D sceneDepth;

layout(location = 10) uniform int premultiplied;
layout(location = 11) uniform float hdrMax;
layout(location = 12) uniform float softDistance;  // <= 0: no soft fade, no depth read
layout(location = 13) uniform vec2 nearFar;
layout(location = 14) uniform vec2 depthTexelsPerPixel;

layout(location = 0) out vec4 outColor;

// Distance from the camera of a [0, 1] depth-buffer value under a perspective projection.
float linearDepth(float depth, float near, float far) {
    return near * far / max(far - depth * (far - near), 1e-6);
}

void main() {
    float shape;
    if (emitterFlags.y > 0.5) {
        shape = texture(sprite, corner * 0.5 + 0.5).a;
    } else {
        shape = 1.0 - smoothstep(0.2, 1.0, length(corner));  // a soft dot
    }
    vec3 emission = clamp(color.rgb, vec3(0.0), vec3(hdrMax));
    // The chapter passes alpha on unclamped (below 0 after a long frame: the blend subtracts).
    float alpha = emitterFlags.z > 0.5 ? color.a : clamp(color.a, 0.0, 1.0);
    alpha *= shape;

    if (softDistance > 0.0) {
        ivec2 texel = ivec2(gl_FragCoord.xy * depthTexelsPerPixel);
        float scene = linearDepth(texelFetch(sceneDepth, texel, 0).r, nearFar.x, nearFar.y);
        // Behind the scene's surface: 0 (the depth test, done here); in front: a smooth ramp.
        float fade = smoothstep(0.0, 1.0, clamp((scene - viewDistance) / max(softDistance, 1e-4), 0.0, 1.0));
        alpha *= fade;
    }

    if (premultiplied == 1) {
        outColor = vec4(emission * alpha, alpha * emitterFlags.x);
    } else {
        outColor = vec4(emission, alpha);
    }
}
