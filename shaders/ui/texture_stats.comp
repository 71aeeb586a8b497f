#version 450 core
// What is in one level of a texture, counted on the GPU (ui/gpu_texture_stats.hpp), so the inspector
// reads back a few hundred bytes instead of the whole texture. The same numbers as analyseImage in
// ui/texture_analysis.cpp:
//   mode 0: per channel the finite min, max and count, NaN, infinite and negative counts; per texel
//           NaN, else infinite, else negative; depth texels at the far plane; the smallest positive
//           value; and each workgroup's sum of the finite values (added up in mode 2);
//   mode 1: the histogram over [low, high] (equal steps, or equal ratios when logarithmic);
//   mode 2: one workgroup adds up the partial sums of mode 0.
// Workgroups stride over the texture, so at most 16x16 of them run, whatever its size.
layout(local_size_x = 16, local_size_y = 16) in;

layout(binding = 0) uniform sampler2D source;
layout(location = 0) uniform int mode;
layout(location = 1) uniform int level;
layout(location = 2) uniform int channels;
layout(location = 3) uniform bool linearDepth;  // channel 0 holds depth: count distances instead
layout(location = 4) uniform float cameraNear;
layout(location = 5) uniform float cameraFar;
layout(location = 6) uniform float low;
layout(location = 7) uniform float high;
layout(location = 8) uniform bool logarithmic;
layout(location = 9) uniform int bins;
layout(location = 10) uniform int partialCount;

// Floats as unsigned integers that order as the floats do, for atomicMin and atomicMax.
uint orderedBits(float f) {
    uint u = floatBitsToUint(f);
    return (u & 0x80000000u) != 0u ? ~u : u | 0x80000000u;
}

layout(std430, binding = 0) buffer Totals {
    uvec4 minBits;       // orderedBits of the finite minimum per channel
    uvec4 maxBits;
    uvec4 finiteCount;
    uvec4 nanCount;
    uvec4 infCount;
    uvec4 negativeCount;
    uvec4 texelCounts;   // NaN texels, infinite texels, negative texels, far-plane texels
    vec4 sum;            // of the finite values per channel (mode 2)
    uint smallestPositive;  // floatBitsToUint of the smallest finite value > 0 (positive floats order as uints)
} totals;

layout(std430, binding = 1) buffer Partials {
    vec4 partialSum[];
};

layout(std430, binding = 2) buffer Histogram {
    uint counts[];  // [channel * bins + bin]
};

// Each thread counts into its own variables, then into the workgroup's shared ones, and one thread per
// workgroup adds those to the totals: a few global atomics per workgroup instead of one per value.
shared vec4 groupSum[256];
shared uint groupMin[4], groupMax[4], groupFinite[4], groupNan[4], groupInf[4], groupNegative[4];
shared uint groupTexels[4], groupSmallest;
shared uint groupBins[4 * 256];  // the histogram, at most 256 bins per channel

float linearize(float depth) {
    float z = depth * 2.0 - 1.0;
    return 2.0 * cameraNear * cameraFar / max(cameraFar + cameraNear - z * (cameraFar - cameraNear), 1e-30);
}

float fraction(float v) {
    if (logarithmic) return v > low ? log(v / low) / log(high / low) : 0.0;
    return high > low ? (v - low) / (high - low) : 0.0;
}

void reduceSums(uint index) {
    barrier();
    for (uint stride = 128u; stride > 0u; stride >>= 1u) {
        if (index < stride) groupSum[index] += groupSum[index + stride];
        barrier();
    }
}

void main() {
    uint index = gl_LocalInvocationIndex;
    if (mode == 2) {
        vec4 s = vec4(0.0);
        for (int i = int(index); i < partialCount; i += 256) s += partialSum[i];
        groupSum[index] = s;
        reduceSums(index);
        if (index == 0u) totals.sum = groupSum[0];
        return;
    }
    if (index < 4u) {
        groupMin[index] = 0xffffffffu;
        groupMax[index] = 0u;
        groupFinite[index] = groupNan[index] = groupInf[index] = groupNegative[index] = groupTexels[index] = 0u;
    }
    if (index == 0u) groupSmallest = 0x7f800000u;
    for (uint b = index; b < uint(4 * bins) && mode == 1; b += 256u) groupBins[b] = 0u;
    barrier();

    uvec4 lowest = uvec4(0xffffffffu), highest = uvec4(0u);
    uvec4 finiteN = uvec4(0u), nanN = uvec4(0u), infN = uvec4(0u), negativeN = uvec4(0u), texelsN = uvec4(0u);
    uint smallest = 0x7f800000u;
    vec4 sum = vec4(0.0);
    // Whole vectors rather than a loop over channels: a software renderer runs that far faster.
    const bvec4 used = lessThan(ivec4(0, 1, 2, 3), ivec4(channels));
    const uvec4 on = uvec4(used);
    ivec2 size = textureSize(source, level);
    ivec2 stride = ivec2(gl_NumWorkGroups.xy * gl_WorkGroupSize.xy);
    for (int y = int(gl_GlobalInvocationID.y); y < size.y; y += stride.y) {
        for (int x = int(gl_GlobalInvocationID.x); x < size.x; x += stride.x) {
            vec4 v = texelFetch(source, ivec2(x, y), level);
            if (mode == 0) {
                // The texel as stored: NaN first, then infinite, then negative.
                bool nan = any(bvec4(uvec4(isnan(v)) * on));
                bool inf = any(bvec4(uvec4(isinf(v)) * on));
                bool negative = any(bvec4(uvec4(lessThan(v, vec4(0.0))) * uvec4(not(isinf(v))) * on));
                texelsN.xyz += uvec3(nan, !nan && inf, !nan && !inf && negative);
            }
            // The values as the view shows them: depth as distance, the far plane (the sky) apart.
            if (linearDepth) {
                if (v.x >= 1.0) {
                    texelsN.w += 1u;
                    v.x = uintBitsToFloat(0x7f800000u);  // +Inf: out of the finite range and the bins
                } else if (!isinf(v.x) && !isnan(v.x)) {
                    v.x = linearize(v.x);
                }
            }
            uvec4 isNan = uvec4(isnan(v)) * on, isInf = uvec4(isinf(v)) * on;
            uvec4 finite = on - isNan - isInf;  // isnan and isinf never both hold
            bvec4 keep = bvec4(finite);
            if (mode == 1) {
                if (!any(keep)) continue;
                ivec4 bin = clamp(ivec4(vec4(fraction(v.x), fraction(v.y), fraction(v.z), fraction(v.w)) * float(bins)),
                                  ivec4(0), ivec4(bins - 1));
                if (keep.x) atomicAdd(groupBins[bin.x], 1u);
                if (keep.y) atomicAdd(groupBins[bins + bin.y], 1u);
                if (keep.z) atomicAdd(groupBins[2 * bins + bin.z], 1u);
                if (keep.w) atomicAdd(groupBins[3 * bins + bin.w], 1u);
                continue;
            }
            nanN += isNan;
            infN += isInf;
            finiteN += finite;
            negativeN += finite * uvec4(lessThan(v, vec4(0.0)));
            uvec4 bits = floatBitsToUint(v);
            uvec4 ordered = mix(bits | 0x80000000u, ~bits, notEqual(bits & 0x80000000u, uvec4(0u)));
            lowest = min(lowest, mix(uvec4(0xffffffffu), ordered, keep));
            highest = max(highest, mix(uvec4(0u), ordered, keep));
            // Positive floats order as their bits do.
            uvec4 positive = mix(uvec4(0x7f800000u), bits, bvec4(finite * uvec4(greaterThan(v, vec4(0.0)))));
            smallest = min(smallest, min(min(positive.x, positive.y), min(positive.z, positive.w)));
            sum += mix(vec4(0.0), v, keep);  // a select, so a NaN elsewhere cannot leak in
        }
    }
    if (mode == 1) {
        barrier();
        for (uint b = index; b < uint(channels * bins); b += 256u)
            if (groupBins[b] != 0u) atomicAdd(counts[b], groupBins[b]);
        return;
    }
    for (int c = 0; c < 4; ++c) {
        if (finiteN[c] != 0u) {
            atomicMin(groupMin[c], lowest[c]);
            atomicMax(groupMax[c], highest[c]);
            atomicAdd(groupFinite[c], finiteN[c]);
            atomicAdd(groupNegative[c], negativeN[c]);
        }
        if (nanN[c] != 0u) atomicAdd(groupNan[c], nanN[c]);
        if (infN[c] != 0u) atomicAdd(groupInf[c], infN[c]);
        if (texelsN[c] != 0u) atomicAdd(groupTexels[c], texelsN[c]);
    }
    atomicMin(groupSmallest, smallest);
    groupSum[index] = sum;
    reduceSums(index);
    if (index < 4u) {
        uint c = index;
        atomicMin(totals.minBits[c], groupMin[c]);
        atomicMax(totals.maxBits[c], groupMax[c]);
        atomicAdd(totals.finiteCount[c], groupFinite[c]);
        atomicAdd(totals.nanCount[c], groupNan[c]);
        atomicAdd(totals.infCount[c], groupInf[c]);
        atomicAdd(totals.negativeCount[c], groupNegative[c]);
        atomicAdd(totals.texelCounts[c], groupTexels[c]);
    }
    if (index == 0u) {
        atomicMin(totals.smallestPositive, groupSmallest);
        partialSum[gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x] = groupSum[0];
    }
}
