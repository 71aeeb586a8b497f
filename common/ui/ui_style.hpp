#pragma once
// Colours and sizes the overlay's panels share, so a channel, a culled pass or a NaN looks the same
// everywhere. The marks for special values are the ones shaders/ui/view_common.glsl paints.
#include <imgui.h>

namespace fx::ui_style {

inline const ImVec4 kMuted{0.55f, 0.55f, 0.55f, 1.0f};  // culled passes, textures not made
inline const ImVec4 kHeading{1.0f, 0.85f, 0.4f, 1.0f};  // step titles, selected names
inline const ImVec4 kError{1.0f, 0.35f, 0.35f, 1.0f};
inline const ImVec4 kWarning{1.0f, 0.7f, 0.3f, 1.0f};
inline const ImVec4 kNotice{0.45f, 0.9f, 1.0f, 1.0f};    // a key's confirmation (F12's file, a reload)
inline const ImVec4 kNan{1.0f, 0.0f, 1.0f, 1.0f};        // magenta
inline const ImVec4 kInf{1.0f, 0.78f, 0.0f, 1.0f};       // amber
inline const ImVec4 kNegative{0.0f, 0.67f, 1.0f, 1.0f};  // azure

inline ImVec4 channelColour(int channel) {
    switch (channel) {
        case 0:
            return {1.0f, 0.42f, 0.42f, 1.0f};
        case 1:
            return {0.45f, 0.95f, 0.45f, 1.0f};
        case 2:
            return {0.45f, 0.65f, 1.0f, 1.0f};
        default:
            return {0.85f, 0.85f, 0.85f, 1.0f};
    }
}

inline ImU32 packed(const ImVec4& colour, float alpha = 1.0f) {
    return ImGui::ColorConvertFloat4ToU32(ImVec4(colour.x, colour.y, colour.z, colour.w * alpha));
}

// Continues the current row when an item `width` pixels wide still fits on it, else starts a new
// row: controls that wrap instead of being cut off when a window is narrow.
void continueRow(float width, float spacing = -1.0f);

// "1.25 MiB", "640 KiB", "96 B"
const char* byteSizeText(unsigned long long bytes, char* buffer, int size);

}  // namespace fx::ui_style
