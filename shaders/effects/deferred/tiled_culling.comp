#version 450 core
// Tiled light culling: one work group per 16 x 16 pixel tile finds the nearest and farthest surface
// depth in its tile, bounds the tile's slice of the view frustum between them with a box in view space,
// and lists the point lights whose sphere (centre, radius: where the light reaches zero) touches the
// box. The lighting pass then loops over the tile's list instead of every light.
// The list is in light order whatever order the threads finish in (a bit per light, compacted by one
// thread), so the picture is the same in every run. A tile with no surface lists nothing.
#include "point_lights.glsl"

#include "deferred_bindings.glsl"

layout(local_size_x = TILE_SIZE, local_size_y = TILE_SIZE) in;

layout(binding = kCullDepthBinding) uniform sampler2D depthTarget;
layout(std430, binding = kTileLightsBinding) writeonly buffer TileLights {
    uint tileLights[];  // per tile: the count, then up to MAX_TILE_LIGHTS indices
};
layout(r32f, binding = kCullHeatBinding) uniform writeonly image2D heat;  // lights touching each tile (before the cap)

layout(location = kCullViewLocation) uniform mat4 viewMatrix;
layout(location = kCullInverseProjectionLocation) uniform mat4 inverseProjection;

const int kMaxLights = 1024;
shared uint minDepthBits;
shared uint maxDepthBits;
shared uint touched[kMaxLights / 32];
shared vec3 boxMin;
shared vec3 boxMax;

vec3 viewPoint(vec2 pixel, float depth, vec2 size) {
    vec4 h = inverseProjection * vec4(pixel / size * 2.0 - 1.0, depth * 2.0 - 1.0, 1.0);
    return h.xyz / (abs(h.w) > 1e-30 ? h.w : 1.0);
}

void main() {
    ivec2 size = textureSize(depthTarget, 0);
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    uint local = gl_LocalInvocationIndex;
    if (local == 0u) {
        minDepthBits = floatBitsToUint(1.0);
        maxDepthBits = 0u;
    }
    for (uint w = local; w < uint(kMaxLights / 32); w += gl_WorkGroupSize.x * gl_WorkGroupSize.y) touched[w] = 0u;
    barrier();
    if (all(lessThan(pixel, size))) {
        float d = texelFetch(depthTarget, pixel, 0).r;
        if (d < 1.0) {  // depths are >= 0, so their bits sort like the numbers
            atomicMin(minDepthBits, floatBitsToUint(d));
            atomicMax(maxDepthBits, floatBitsToUint(d));
        }
    }
    barrier();
    bool empty = maxDepthBits == 0u && minDepthBits == floatBitsToUint(1.0);
    if (local == 0u && !empty) {
        // The tile's corners at its nearest and farthest depth, in view space: their box holds the slice.
        vec2 lo = vec2(gl_WorkGroupID.xy * gl_WorkGroupSize.xy);
        vec2 hi = min(lo + vec2(gl_WorkGroupSize.xy), vec2(size));
        float dn = uintBitsToFloat(minDepthBits), df = uintBitsToFloat(maxDepthBits);
        vec3 bmin = vec3(1e30), bmax = vec3(-1e30);
        for (int c = 0; c < 8; ++c) {
            vec2 corner = vec2((c & 1) != 0 ? hi.x : lo.x, (c & 2) != 0 ? hi.y : lo.y);
            vec3 p = viewPoint(corner, (c & 4) != 0 ? df : dn, vec2(size));
            bmin = min(bmin, p);
            bmax = max(bmax, p);
        }
        boxMin = bmin;
        boxMax = bmax;
    }
    barrier();
    int count = min(pointLightCount, kMaxLights);
    if (!empty) {
        for (int i = int(local); i < count; i += int(gl_WorkGroupSize.x * gl_WorkGroupSize.y)) {
            vec4 pr = pointLights[i].positionRadius;
            if (!(pr.w > 0.0)) continue;  // radius 0 reaches nothing
            vec3 c = (viewMatrix * vec4(pr.xyz, 1.0)).xyz;
            vec3 nearest = clamp(c, boxMin, boxMax);
            vec3 d = c - nearest;
            if (dot(d, d) < pr.w * pr.w) atomicOr(touched[i / 32], 1u << uint(i % 32));
        }
    }
    barrier();
    if (local == 0u) {
        uint tilesX = gl_NumWorkGroups.x;
        uint base = (gl_WorkGroupID.y * tilesX + gl_WorkGroupID.x) * uint(MAX_TILE_LIGHTS + 1);
        uint n = 0u, listed = 0u;
        for (int w = 0; w < kMaxLights / 32; ++w) {
            uint bits = touched[w];
            while (bits != 0u) {
                int b = findLSB(bits);
                bits &= bits - 1u;
                if (listed < uint(MAX_TILE_LIGHTS)) tileLights[base + 1u + listed++] = uint(w * 32 + b);
                ++n;
            }
        }
        tileLights[base] = listed;
        imageStore(heat, ivec2(gl_WorkGroupID.xy), vec4(float(n), 0.0, 0.0, 0.0));
    }
}
