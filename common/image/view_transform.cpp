#include "image/view_transform.hpp"

#include <algorithm>
#include <cmath>

namespace fx {

double encodeSrgb(double linear) {
    if (linear <= 0.0031308) return 12.92 * linear;
    return 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

std::uint8_t toDisplayValue(float value, ViewTransform transform) {
    // NaN compares false with everything, so test it first; it maps to 0 here and callers that
    // care (toDisplay) paint the whole texel magenta instead.
    if (std::isnan(value)) return 0;
    double v = std::clamp(static_cast<double>(value), 0.0, 1.0);
    if (transform == ViewTransform::LinearToSrgb) v = encodeSrgb(v);
    return static_cast<std::uint8_t>(std::lround(v * 255.0));
}

ByteImage toDisplay(const FloatImage& image, ViewTransform transform) {
    ByteImage display = makeByteImage(image.width, image.height, 4, 255);
    const std::size_t count = image.texelCount();
    const auto channels = static_cast<std::size_t>(image.channels);
    for (std::size_t i = 0; i < count; ++i) {
        const float* in = &image.texels[i * channels];
        std::uint8_t* out = &display.texels[i * 4];
        if (std::any_of(in, in + channels, [](float v) { return std::isnan(v); })) {
            out[0] = 255;  // magenta; alpha is already 255
            out[1] = 0;
            out[2] = 255;
            continue;
        }
        const std::uint8_t first = toDisplayValue(in[0], transform);
        switch (image.channels) {
            case 1:
                out[0] = out[1] = out[2] = first;
                break;
            case 2:
                out[0] = first;
                out[1] = toDisplayValue(in[1], transform);
                out[2] = 0;
                break;
            default:
                out[0] = first;
                out[1] = toDisplayValue(in[1], transform);
                out[2] = toDisplayValue(in[2], transform);
                if (image.channels >= 4) out[3] = toDisplayValue(in[3], ViewTransform::Direct);
                break;
        }
    }
    return display;
}

}  // namespace fx
