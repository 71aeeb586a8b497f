#pragma once
// PNG files for 8-bit pictures: captures, golden images, plots.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "base/result.hpp"
#include "image/image.hpp"

namespace fx {

// Writes 1 to 4 channels (grey, grey+alpha, RGB, RGBA) as they are. Rows are flipped to the
// top-down order PNG uses. The file is written atomically: complete, or not there at all.
Status writePng(const std::filesystem::path& path, const ByteImage& image);

// The PNG file's bytes without touching the disk (what writePng writes).
Result<std::vector<std::byte>> encodePng(const ByteImage& image);

// The most pixels an image fxlab reads may have (a texture, a golden image): 8192 x 8192, 256 MiB decoded.
// A larger one is refused from its header, before it is decoded.
inline constexpr std::int64_t kMaxImagePixels = std::int64_t(8192) * 8192;
// Refuses a size past kMaxImagePixels, naming `what` (the file), the size and the limit.
Status checkImagePixels(std::int64_t width, std::int64_t height, const std::string& what);

// Always returns RGBA (4 channels), rows bottom-up like every image here. 16-bit files are
// reduced to 8 bits.
Result<ByteImage> readPng(const std::filesystem::path& path);

// An encoded image in memory (PNG, or any format stb_image reads: glTF embeds them) as RGBA with
// rows bottom-up. `what` names it in the error ("character.gltf image 2").
Result<ByteImage> decodeImage(std::span<const std::byte> encoded, const std::string& what);

}  // namespace fx
