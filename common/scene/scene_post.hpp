#pragma once
// The post-processing a scene asks for. An effect is requested when it is present; its settings start
// from the defaults below. The order the passes run in is the lesson's business, not the scene's.
// Each setting's range, default and help are declared once, in scene/scene_settings.cpp, which also
// hands them to the lessons' parameters; the command line and the overlay override them.
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "base/params.hpp"

namespace fx {

enum class PostEffect { bloom, colorMatrix, radialBlur, depthOfField, toneMap };

struct BloomSettings {
    float threshold = 1.0f;  // brightness where blooming starts
    float knee = 0.5f;       // soft-knee width as a fraction of the threshold; 0 is a hard cut
    float intensity = 1.0f;  // scale of the blurred light added back
    int levels = 6;          // mip levels in the blur chain

    bool operator==(const BloomSettings&) const = default;
};

// The colour transforms that need no numbers of their own (effects/post/colour_matrix.hpp): the
// chapter's two filters, and the affine negative that no 3x3 matrix can make.
enum class ColorMatrixPreset { identity, grayscale, sepia, invert };

struct ColorMatrixSettings {
    ColorMatrixPreset preset = ColorMatrixPreset::grayscale;
    float amount = 1.0f;  // blend from the original (0) to the full matrix (1)

    bool operator==(const ColorMatrixSettings&) const = default;
};

struct RadialBlurSettings {
    glm::vec2 center{0.5f};  // in texture coordinates of the screen
    float length = 0.02f;    // how far the taps reach toward the centre, per unit of distance
    float start = 0.2f;      // radius around the centre that stays sharp
    int taps = 8;

    bool operator==(const RadialBlurSettings&) const = default;
};

// Depth of field reads the camera's lens (focal length, f-number, focus distance), so it needs one.
// Lesson 09 starts max_coc and taps from it.
struct DepthOfFieldSettings {
    float maxCocPixels = 16.0f;  // circle-of-confusion diameter is clamped here
    int taps = 16;

    bool operator==(const DepthOfFieldSettings&) const = default;
};

// How HDR light is squeezed into [0, 1] before the display encoding, per channel. The one vocabulary
// for scene files, lesson parameters and the output transform (effects/post/output_transform_pass.hpp,
// which also has the formulas).
enum class ToneCurve {
    clip,      // none, as in the chapters: values above 1 clip per channel
    reinhard,  // x / (1 + x)
    filmic,    // ACES-style filmic: x (2.51 x + 0.03) / (x (2.43 x + 0.59) + 0.14)
};

struct ToneMapSettings {
    ToneCurve curve = ToneCurve::filmic;
    float exposure = 1.0f;  // multiplies the HDR colour before the curve

    bool operator==(const ToneMapSettings&) const = default;
};

struct PostEffects {
    std::optional<BloomSettings> bloom;
    std::optional<ColorMatrixSettings> colorMatrix;
    std::optional<RadialBlurSettings> radialBlur;
    std::optional<DepthOfFieldSettings> depthOfField;
    std::optional<ToneMapSettings> toneMap;

    bool wants(PostEffect effect) const;
    bool operator==(const PostEffects&) const = default;
};

// The shortest text that reads back as the same float, so a parameter gets exactly the scene's value;
// "infinity" for infinity (a focus distance).
std::string settingNumberText(float value);

}  // namespace fx
