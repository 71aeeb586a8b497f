#include "ui/view_settings.hpp"

namespace fx {

std::string_view toString(DisplayTransform transform) {
    switch (transform) {
        case DisplayTransform::Direct:
            return "as stored";
        case DisplayTransform::Srgb:
            return "linear -> sRGB";
        case DisplayTransform::Reinhard:
            return "Reinhard -> sRGB";
        case DisplayTransform::FalseColour:
            return "false colour";
    }
    return "?";
}

ViewSettings defaultViewSettings(const TextureSpec& spec) {
    ViewSettings s;
    if (isDepth(spec.format)) {
        s.transform = DisplayTransform::Direct;
        s.channels = {true, false, false, false};
    } else if (isFloat(spec.format) || isSrgb(spec.format)) {
        // sRGB textures are decoded to linear light when fetched, so they need the encoding back.
        s.transform = DisplayTransform::Srgb;
    }
    // Fitting the range is right for depth (a narrow band near 1) and harmless for colour only when
    // asked; colour starts at [0, 1] so that a dark picture looks dark.
    s.autoFitPending = isDepth(spec.format);
    return s;
}

bool showsLinearDepth(const ViewSettings& settings, const TextureSpec& spec) {
    return settings.linearDepth && isDepth(spec.format);
}

}  // namespace fx
