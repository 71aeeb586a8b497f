#pragma once
// Radial (zoom) blur, Shader effects §3.6: each pixel averages taps placed on the line from the pixel
// toward a centre, so edges streak along lines through that point. Near the centre a start distance
// keeps the picture sharp. All distances are in texture coordinates of the screen, like the chapter's
// (so the sharp area is an ellipse on a wide screen).
//
// The offset between neighbouring taps, for a pixel at uv with d = centre - uv:
//   first version   v = d * length
//   with a start    v = d * (max(|d| - start, 0) / |d|) * length       (0/0 at the centre pixel)
//   guarded         the same, but v = 0 where |d| <= kRadialBlurCentreEpsilon
// The chapter takes 8 taps, at uv + v*i for i = 0..7, with weights 1/8. With another sample count the
// taps spread over the same streak (7 v long), so the count changes quality, not the size of the blur,
// and the weights stay 1/samples: a uniform image comes out unchanged for every count.
//
// Two passes: "radial blur" makes blur.result; "radial blur offsets" writes the offset v of every pixel
// into blur.offset (RG16F) with the same GLSL. Nothing reads blur.offset, so the graph runs that pass
// only when someone inspects or captures it: the picture costs nothing when nobody looks.
#include <string_view>

#include <glm/vec2.hpp>

#include "effects/post/fullscreen_pass.hpp"
#include "render/frame_graph.hpp"

namespace fx {

enum class RadialBlurFormula {
    firstVersion,  // no start distance: every pixel but the centre is blurred
    chapter,       // the chapter's start-distance formula: divides by |d|, which is 0 at the centre pixel
    guarded,       // the same formula with the limit at the centre defined (no blur there)
};

struct RadialBlurFormulaInfo {
    std::string_view name;
    std::string_view formula;
    bool deliberateBug;  // kept to show the NaN it makes: never the default
};
const RadialBlurFormulaInfo& describe(RadialBlurFormula formula);

// Below this distance (texture coordinates) a pixel counts as sitting on the centre.
inline constexpr float kRadialBlurCentreEpsilon = 1e-6f;
inline constexpr int kRadialBlurMaxSamples = 256;

struct RadialBlurParams {
    glm::vec2 centre{0.5f, 0.5f};  // texture coordinates; outside [0, 1] is allowed (off screen)
    float length = 0.02f;          // the chapter's z: tap spacing per unit of distance. <= 0: no blur
    float start = 0.2f;            // the chapter's w: the radius that stays sharp
    int samples = 8;               // taps per pixel, 1 to kRadialBlurMaxSamples
    RadialBlurFormula formula = RadialBlurFormula::guarded;
    // Moves the centre onto the nearest pixel centre, where the unguarded formula divides 0 by 0. An
    // odd-sized target does that to the default centre (0.5, 0.5); an even-sized one never does.
    bool centreOnPixel = false;
};

// The parameters the effect uses: what a slider or a scene file cannot be trusted to keep in range is
// brought into it here, so the shader and the CPU reference see the same values.
//   length   negative or not finite: 0, no blur (the chapter skips the blur for z <= 0; a negative z
//            would point the taps away from the centre, and an infinite one has no taps left)
//   start    negative or NaN: 0 (a negative w makes |d| - w > |d|: more blur than the formula's
//            largest, and at the centre pixel of the chapter's formula a division by 0)
//   samples  1 to kRadialBlurMaxSamples
// Lengths above 1/7 stay: the far taps then overshoot the centre, as the chapter warns, and lesson 05
// lets that be seen.
RadialBlurParams clampedRadialBlurParams(RadialBlurParams params);

// The centre in framebuffer pixels (bottom-left origin) for a target of `size`. The shader takes the
// centre in pixels, so that a pixel whose centre is the blur centre gets d = 0 exactly.
glm::vec2 radialBlurCentrePixels(const RadialBlurParams& params, Size2D size);

// The offset between taps for the pixel centred at `pixel` (framebuffer pixels), as the shader
// computes it: the CPU reference for tests and the lesson's panel. NaN where the formula is 0/0.
glm::vec2 radialBlurTapOffset(const RadialBlurParams& params, Size2D size, glm::vec2 pixel);

class RadialBlur {
public:
    struct Declared {
        DeclaredPass blur;     // "radial blur" -> blur.result (the format asked for, the output's size)
        DeclaredPass offsets;  // "radial blur offsets" -> blur.offset
    };
    Declared declare(FrameGraph& graph, TextureHandle input, const RadialBlurParams& params,
                     TextureFormat format = TextureFormat::RGBA16F) const;

private:
    FullscreenPass blur_{"effects/post/radial_blur.frag", "radial blur"};
    FullscreenPass offsets_{"effects/post/radial_blur_offset.frag", "radial blur offsets"};
    // Linear, clamp to edge: the taps need bilinear filtering, and a tap past the edge must read the
    // edge, not the opposite side (REPEAT). Bound for the draw, so whatever parameters the input
    // texture carries are not inherited.
    gl::SamplerName sampler_ = gl::createLinearClampSampler("radial blur (linear, clamp to edge)");
};

}  // namespace fx
