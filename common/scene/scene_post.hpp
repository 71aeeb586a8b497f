#pragma once
// The post-processing a scene asks for. An effect is requested when it is present; its settings start
// from the defaults below. The order the passes run in is the lesson's business, not the scene's.
#include <optional>

#include <glm/vec2.hpp>

namespace fx {

enum class PostEffect { bloom, colorMatrix, radialBlur, depthOfField, toneMap };

struct BloomSettings {
    float threshold = 1.0f;  // brightness where blooming starts
    float knee = 0.5f;       // soft-knee width as a fraction of the threshold; 0 is a hard cut
    float intensity = 1.0f;  // scale of the blurred light added back
    int levels = 6;          // mip levels in the blur chain

    bool operator==(const BloomSettings&) const = default;
};

enum class ColorMatrixPreset { identity, grayscale, sepia };

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
struct DepthOfFieldSettings {
    float maxCocPixels = 16.0f;  // circle-of-confusion diameter is clamped here
    int taps = 16;

    bool operator==(const DepthOfFieldSettings&) const = default;
};

enum class ToneMapOperator { linear, reinhard, aces };

struct ToneMapSettings {
    ToneMapOperator toneOperator = ToneMapOperator::aces;
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

}  // namespace fx
