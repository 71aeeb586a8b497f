#pragma once
// The numbers the cloud pass hands its shader, computed on the CPU where a division can be guarded
// once (the Clouds chapter's uniforms 103, 104 and 106, and the hard cases of its part 8). GL-free,
// so the guards are unit-tested without a context.
//
//   CloudScroll scroll;                       // the chapter's starting offsets (0, 0, 0.3, 0.7)
//   scroll.advance(speeds, frame.deltaSeconds);   // every frame: wrapped into [0, 1)
//   CloudMarch march = cloudMarch(bottom, top, steps, threshold);
#include <array>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

namespace fx {

// The most samples a ray takes (the bench's reference is 512).
inline constexpr int kCloudMaxSteps = 512;

// The two noise layers' texture offsets, in texture units: xy for layer 0, zw for layer 1.
//
// The chapter adds speed x dt to a float that grows for ever. The fastest layer moves 0.0041 units a
// second, 6.8e-5 a frame at 60 Hz; once the offset passes about 2048 the float's spacing is larger than
// that and the clouds stop (about 139 hours), and long before that the speed is visibly quantised.
// The texture repeats every unit (GL_REPEAT), so only the fraction matters: each component is kept in
// [0, 1) after every step, in double, and the shader gets a float that is always small.
class CloudScroll {
public:
    CloudScroll() = default;
    explicit CloudScroll(glm::dvec4 start);

    // Moves each component by speed x seconds and wraps it into [0, 1). Non-finite speeds or times
    // leave the offset where it is.
    void advance(const glm::dvec4& speedPerSecond, double seconds);
    // The offset as the shader gets it.
    glm::vec4 offset() const { return glm::vec4(offset_); }
    const glm::dvec4& exact() const { return offset_; }

    // The offset after `seconds` of scrolling from `start`, in one step (what a run of that length
    // reaches, up to rounding): for tests and for a clock that jumps.
    static CloudScroll at(const glm::dvec4& start, const glm::dvec4& speedPerSecond, double seconds);

private:
    glm::dvec4 offset_{0.0, 0.0, 0.3, 0.7};  // the chapter's starting offsets
};

// v minus its floor, in [0, 1): where a texture coordinate lands in a repeating texture.
double wrapUnit(double v);

// The chapter's own update, for comparison: a float that is never wrapped (the pitfall). Returns the
// offset after one more step of `seconds`.
glm::vec4 unwrappedCloudOffsetStep(const glm::vec4& offset, const glm::vec4& speedPerSecond, float seconds);

// The slab and the march as the shader gets them, every hard case turned into "no cloud" or a
// finite value:
//  - steps: a non-integer count from the overlay is rounded down, and the vertical step is computed
//    from the same whole number, so the samples always cross the whole slab (the chapter computes the
//    step from 8.5 and runs 8 samples); below 1: no samples, step 0 (the chapter uploads infinity);
//  - bottom == top (or top below bottom): thickness 0, nothing to march, no division by it;
//  - threshold 1 (or more, or NaN): 1/(1 - threshold) would be infinite and 0 x infinity NaN on every
//    sample at or below the threshold: gain 0 and `drawn` false instead. A threshold just below 1
//    keeps its large gain; the per-sample opacity is clamped to 1 in the shader.
struct CloudMarch {
    float bottom = 0.0f;
    float top = 2.0f;
    int steps = 8;
    float stepHeight = 0.25f;      // (top - bottom) / steps: the vertical distance between samples
    float threshold = 0.5f;        // density at or below it is clear sky
    float thresholdGain = 2.0f;    // 1 / (1 - threshold), 0 when the threshold leaves no cloud
    bool drawn = true;             // false: no slab to march (no thickness or no samples)
    bool thresholdClears = false;  // true: the threshold leaves no cloud at all (1 or more)

    glm::vec4 rangeCountStep() const { return {bottom, top, float(steps), stepHeight}; }
    glm::vec2 thresholdPair() const { return {threshold, thresholdGain}; }
};

CloudMarch cloudMarch(float bottom, float top, float steps, float threshold);

// The chapter's 4x4 Bayer matrix, k/16 for row y mod 4 and column x mod 4 of the window pixel: the
// fraction of a step the ray start moves forward (the shader has the same table).
float bayer4x4(int x, int y);

// Interleaved gradient noise (Jimenez 2014) at a pixel, in [0, 1): a dither whose neighbours differ as
// much as possible; with `frame` it moves every frame (a 5.588238-pixel shift per frame), so an average
// over frames sees every offset. Plain float maths on small numbers, the same in C++ and GLSL.
float interleavedGradientNoise(float x, float y, int frame);

}  // namespace fx
