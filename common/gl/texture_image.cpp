#include "gl/texture_image.hpp"

#include "gl/device_limits.hpp"
#include "image/png_file.hpp"

namespace fx::gl {
namespace {

Result<ByteImage> fitting(Result<ByteImage> image, const std::string& what) {
    if (!image) return image;
    if (Status fits = checkTextureSize(queryDeviceLimits(), image->width, image->height, what); !fits)
        return Error{fits.error()};
    return image;
}

}  // namespace

Result<ByteImage> readTextureImage(const std::filesystem::path& path) {
    return fitting(readPng(path), path.string());
}

Result<ByteImage> decodeTextureImage(std::span<const std::byte> encoded, const std::string& what) {
    return fitting(decodeImage(encoded, what), what);
}

}  // namespace fx::gl
