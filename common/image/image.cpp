#include "image/image.hpp"

#include <algorithm>

#include "base/log.hpp"

namespace fx {
namespace {

template <class Texel>
Image<Texel> makeImage(int width, int height, int channels, Texel fill) {
    Image<Texel> image;
    image.width = std::max(width, 0);
    image.height = std::max(height, 0);
    image.channels = std::max(channels, 0);
    image.texels.assign(
        static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * image.channels,
        fill);
    return image;
}

}  // namespace

FloatImage makeFloatImage(int width, int height, int channels, float fill) {
    return makeImage<float>(width, height, channels, fill);
}

ByteImage makeByteImage(int width, int height, int channels, std::uint8_t fill) {
    return makeImage<std::uint8_t>(width, height, channels, fill);
}

template <class Texel>
std::string describeShape(const Image<Texel>& image) {
    return cat(image.width, "x", image.height, ", ", image.channels,
               image.channels == 1 ? " channel" : " channels");
}

template <class Texel>
Status checkShape(const Image<Texel>& image, const std::string& what) {
    if (image.width < 0 || image.height < 0)
        return Error{cat(what, " has a negative size (", describeShape(image), ")")};
    if (image.channels < 1 || image.channels > 4)
        return Error{cat(what, " has ", image.channels, " channels; 1 to 4 are supported")};
    const auto expected = static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) *
                          static_cast<std::size_t>(image.channels);
    if (image.texels.size() != expected)
        return Error{cat(what, " holds ", image.texels.size(), " values but ", describeShape(image),
                         " needs ", expected)};
    return Status::success();
}

template <class Texel>
Image<Texel> flippedVertically(const Image<Texel>& image) {
    Image<Texel> flipped = image;
    if (image.empty()) return flipped;
    const std::size_t rowLength = static_cast<std::size_t>(image.width) * image.channels;
    for (int y = 0; y < image.height; ++y) {
        auto source = image.texels.begin() + static_cast<std::ptrdiff_t>(rowLength * y);
        auto target =
            flipped.texels.begin() + static_cast<std::ptrdiff_t>(rowLength * (image.height - 1 - y));
        std::copy(source, source + static_cast<std::ptrdiff_t>(rowLength), target);
    }
    return flipped;
}

ByteImage toRgba(const ByteImage& image) {
    if (image.channels == 4) return image;
    ByteImage rgba = makeByteImage(image.width, image.height, 4, 255);
    const std::size_t count = image.texelCount();
    const auto channels = static_cast<std::size_t>(image.channels);
    for (std::size_t i = 0; i < count; ++i) {
        const std::uint8_t* in = &image.texels[i * channels];
        std::uint8_t* out = &rgba.texels[i * 4];
        switch (image.channels) {
            case 1:
                out[0] = out[1] = out[2] = in[0];
                break;
            case 2:
                out[0] = in[0];
                out[1] = in[1];
                out[2] = 0;
                break;
            default:
                out[0] = in[0];
                out[1] = in[1];
                out[2] = in[2];
                break;
        }
    }
    return rgba;
}

FloatImage toFloatImage(const ByteImage& image) {
    FloatImage result = makeFloatImage(image.width, image.height, image.channels);
    std::transform(image.texels.begin(), image.texels.end(), result.texels.begin(),
                   [](std::uint8_t v) { return static_cast<float>(v) / 255.0f; });
    return result;
}

template std::string describeShape(const Image<float>&);
template std::string describeShape(const Image<std::uint8_t>&);
template Status checkShape(const Image<float>&, const std::string&);
template Status checkShape(const Image<std::uint8_t>&, const std::string&);
template Image<float> flippedVertically(const Image<float>&);
template Image<std::uint8_t> flippedVertically(const Image<std::uint8_t>&);

}  // namespace fx
