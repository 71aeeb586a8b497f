#pragma once
// Images on the CPU: captures read back from the GPU, pictures loaded from files, plots drawn here.
//
// Texels are row-major with interleaved channels, and rows run BOTTOM-UP: row 0 is the bottom of
// the picture. That is the order glReadPixels and glGetTexImage return, so a capture is stored as
// it arrives and only the file writers flip it (PNG stores rows top-down; PFM is bottom-up too).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "base/result.hpp"

namespace fx {

template <class Texel>
struct Image {
    int width = 0, height = 0, channels = 0;
    std::vector<Texel> texels;

    // (x, y) with y counted from the bottom row; c is the channel (0 = red or grey).
    std::size_t index(int x, int y, int c) const {
        return (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) *
                   static_cast<std::size_t>(channels) +
               static_cast<std::size_t>(c);
    }
    Texel& texel(int x, int y, int c) { return texels[index(x, y, c)]; }
    const Texel& texel(int x, int y, int c) const { return texels[index(x, y, c)]; }

    bool empty() const { return width <= 0 || height <= 0 || channels <= 0; }
    std::size_t texelCount() const { return empty() ? 0 : static_cast<std::size_t>(width) * height; }
};

// Linear or HDR values as the GPU stores them (any float, NaN and infinities included).
using FloatImage = Image<float>;
// Display-ready 8-bit values (UNORM, sRGB-encoded when they came through the view transform).
using ByteImage = Image<std::uint8_t>;

FloatImage makeFloatImage(int width, int height, int channels, float fill = 0.0f);
ByteImage makeByteImage(int width, int height, int channels, std::uint8_t fill = 0);

// "64x32, 4 channels": how errors and verdicts name an image's shape.
template <class Texel>
std::string describeShape(const Image<Texel>& image);

// Checks what every reader of an image relies on: 1 to 4 channels, non-negative sizes and exactly
// width * height * channels texels. `what` names the image in the message ("golden image").
template <class Texel>
Status checkShape(const Image<Texel>& image, const std::string& what);

// The same picture with its rows in the opposite order (bottom-up <-> top-down).
template <class Texel>
Image<Texel> flippedVertically(const Image<Texel>& image);

// Widens any channel count to RGBA the way the display does: grey -> (g, g, g), (r, g) -> (r, g, 0),
// and alpha 255 when the source has none.
ByteImage toRgba(const ByteImage& image);

// 8-bit UNORM to float in [0, 1] (value / 255), channels unchanged.
FloatImage toFloatImage(const ByteImage& image);

}  // namespace fx
