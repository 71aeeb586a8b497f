#pragma once
// An image a scene names (a material's texture, a cloud's density, a particle sprite, an image inside a
// glTF file), read for a texture of this device: refused with the file, its size and the limit when a
// side is longer than the GPU's textures may be, instead of a GL_INVALID_VALUE at upload.
#include <cstddef>
#include <filesystem>
#include <span>
#include <string>

#include "base/result.hpp"
#include "image/image.hpp"

namespace fx::gl {

Result<ByteImage> readTextureImage(const std::filesystem::path& path);
Result<ByteImage> decodeTextureImage(std::span<const std::byte> encoded, const std::string& what);

}  // namespace fx::gl
