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

ViewSettings defaultViewSettings(const gl::TextureInfo& info) {
    ViewSettings s;
    if (gl::isDepthFormat(info.internalFormat)) {
        s.transform = DisplayTransform::Direct;
        s.channels = {true, false, false, false};
    } else if (gl::isFloatFormat(info.internalFormat) || info.internalFormat == GL_SRGB8_ALPHA8) {
        // sRGB textures are decoded to linear light when fetched, so they need the encoding back.
        s.transform = DisplayTransform::Srgb;
    }
    // Fitting the range is right for depth (a narrow band near 1) and harmless for colour only when
    // asked; colour starts at [0, 1] so that a dark picture looks dark.
    s.autoFitPending = gl::isDepthFormat(info.internalFormat);
    return s;
}

bool showsLinearDepth(const ViewSettings& settings, const gl::TextureInfo& info) {
    return settings.linearDepth && gl::isDepthFormat(info.internalFormat);
}

}  // namespace fx
