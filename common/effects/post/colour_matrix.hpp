#pragma once
// Colour conversion by a matrix (the Shader effects chapter, §3.5), applied to linear HDR colour before the
// output transform. The chapter's filters (grayscale, sepia) are 3x3 matrices; an inverted picture is
// not, because a matrix maps black to black and the negative must map it to white. So the transform
// here is affine, a matrix and an offset:
//
//     rgb' = matrix * rgb + offset
//
// which covers everything a 3x3 does (offset 0) and adds invert (-I, offset 1) and brightness (an
// added constant). The maths lives on the CPU as well (ColourTransform::apply): the tests use it as
// the reference for the shader, and the lesson composes and blends transforms with it before upload.
//
// The API (the chapter's Exercise 02, answered in lessons/04_colour_matrix/lesson.md): one setter
// that takes a transform value, with the presets as named constructors of that value.
//
//   ColourMatrixPass grading;
//   grading.setTransform(ColourTransform::sepia());
//   DeclaredPass graded = grading.declare(graph, hdr.color);   // creates "colour.graded"
#include <array>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "effects/post/fullscreen_pass.hpp"
#include "render/frame_graph.hpp"

namespace fx {

// Rec.709 luma weights for linear RGB (they add up to 1, so white stays white).
inline constexpr float kLumaR = 0.2126f, kLumaG = 0.7152f, kLumaB = 0.0722f;

struct ColourTransform {
    // Column-major like GLSL's mat3: matrix[c] is column c, the weight of input channel c in each
    // output channel. Build from rows with fromRows() to write a filter as its per-channel equations.
    glm::mat3 matrix{1.0f};
    glm::vec3 offset{0.0f};

    // rgb' = matrix * rgb + offset.
    glm::vec3 apply(const glm::vec3& rgb) const { return matrix * rgb + offset; }
    // The equation of one output channel (0 red, 1 green, 2 blue): its weights for r, g and b.
    glm::vec3 row(int channel) const;
    // True when a bare 3x3 matrix can do it (no offset).
    bool linear() const { return offset == glm::vec3(0.0f); }

    // Each row is one output channel's weights: red' = dot(red, rgb) + offset.r, and so on.
    static ColourTransform fromRows(const glm::vec3& red, const glm::vec3& green, const glm::vec3& blue,
                                    const glm::vec3& offset = glm::vec3(0.0f));

    // --- The chapter's presets ---
    static ColourTransform identity() { return {}; }
    // Every channel becomes the Rec.709 luma 0.2126 r + 0.7152 g + 0.0722 b.
    static ColourTransform grayscale();
    // The chapter's sepia (values it credits to yoya's Qiita article). Its rows add up to 1.175,
    // 0.948 and 0.670, so white becomes (1.175, 0.948, 0.670): warm, and clipped in red.
    static ColourTransform sepia();

    // --- Beyond the chapter ---
    // Mixes each colour with its luma: 0 is grayscale, 1 leaves the image alone, above 1 pushes colours
    // apart (and saturated ones below zero), -1 gives the complement around the grey.
    static ColourTransform saturation(float amount);
    // Turns hues around the grey axis (1, 1, 1) by `degrees`. Greys stay, saturated colours can leave
    // [0, 1] on either side.
    static ColourTransform hueRotation(float degrees);
    // Output channel i takes input channel source[i] (0 r, 1 g, 2 b): {1, 2, 0} is (g, b, r).
    static ColourTransform channelSwap(const std::array<int, 3>& source);
    // Contrast scales the distance from mid grey (linear 0.18, which shows as about 46 % grey), then
    // brightness is added. The added brightness is the offset a 3x3 matrix cannot hold.
    static ColourTransform brightnessContrast(float brightness, float contrast);
    // The negative, 1 - c: matrix -I and offset 1. Meant for display-range values: HDR values above 1
    // become negative and are clamped to black.
    static ColourTransform invert();
    // The best a bare 3x3 can do towards a negative: -I. Every channel comes out zero or negative,
    // which is clamped to black (and would be NaN in the chapter's pow(c, 1/2.2)).
    static ColourTransform negate();
};

// Applies `first`, then `second`: matrix = second.matrix * first.matrix,
// offset = second.matrix * first.offset + second.offset.
ColourTransform then(const ColourTransform& first, const ColourTransform& second);
// Blends from the identity (amount 0) to `t` (amount 1), as the scene file's "amount" does. A blend of
// affine maps is affine, so the result is exact, not an approximation.
ColourTransform blendFromIdentity(const ColourTransform& t, float amount);

// Mid grey in linear light, the pivot of brightnessContrast().
inline constexpr float kMidGrey = 0.18f;

// The GPU pass: reads linear HDR colour, writes colour.graded (RGBA16F, the size of the output),
// clamped to [0, kSceneHdrMax]: a matrix can make channels negative (saturation above 1, hue rotation,
// -I), and negative light means nothing to the passes and the encoding after it (the chapter's pow of
// a negative value is NaN).
class ColourMatrixPass {
public:
    // Exercise 02: the one way to choose the conversion. The initial state is the identity.
    void setTransform(const ColourTransform& transform) { transform_ = transform; }
    const ColourTransform& transform() const { return transform_; }

    // Declares "colour matrix" with the transform set now.
    DeclaredPass declare(FrameGraph& graph, TextureHandle input,
                         TextureFormat format = TextureFormat::RGBA16F) const;

private:
    FullscreenPass pass_{"effects/post/colour_matrix.frag", "colour matrix"};
    ColourTransform transform_;
};

}  // namespace fx
