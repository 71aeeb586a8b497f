#pragma once
// How the inspector shows one texture: which level, which channels, the value range, exposure, the
// view transform, depth linearisation and the highlight of special values. Kept per texture name,
// so going back to a texture finds it as it was left (as RenderDoc does).
#include <array>
#include <string_view>

#include "base/texture_spec.hpp"

namespace fx {

// The view transforms of the inspector; the first two are image/view_transform.hpp's.
enum class DisplayTransform {
    Direct,      // values as they are, clamped: UNORM colour, masks, depth
    Srgb,        // linear light encoded for the screen: float targets
    Reinhard,    // x / (1 + x), then sRGB: HDR light without clipping the highlights
    FalseColour  // the largest channel on a cold-to-hot ramp: depth, heat maps, small differences
};

inline constexpr int kDisplayTransformCount = 4;
std::string_view toString(DisplayTransform transform);

struct ViewSettings {
    int level = 0;
    std::array<bool, 4> channels{true, true, true, false};  // R, G, B, A
    DisplayTransform transform = DisplayTransform::Direct;
    float exposureStops = 0.0f;               // the mapped value is multiplied by 2^stops
    float rangeLow = 0.0f, rangeHigh = 1.0f;  // shown as black and as white
    bool highlightSpecial = false;            // grey picture, NaN / Inf / negative texels in colour
    bool linearDepth = true;                  // depth formats: show distance, not the stored value
    float cameraNear = 0.1f, cameraFar = 100.0f;
    bool autoFitPending = true;  // fit the range to the data once it has been read
};

// What a texture of this format is best looked at with first: float colour as linear light, depth
// linearised and fitted to its range, everything else as stored.
ViewSettings defaultViewSettings(const TextureSpec& spec);

// True when the transform and range make depth a distance (the probe says so next to the value).
bool showsLinearDepth(const ViewSettings& settings, const TextureSpec& spec);

}  // namespace fx
