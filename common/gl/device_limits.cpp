#include "gl/device_limits.hpp"

#include <algorithm>

#include "base/log.hpp"
#include "gl/gl.hpp"

namespace fx::gl {

DeviceLimits queryDeviceLimits() {
    DeviceLimits limits;
    GLint texture = 0, groups = 0;
    GLint64 storage = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &texture);
    glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, 0, &groups);
    glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &storage);
    // A query that gave nothing (no context, an error) leaves GL 4.5's guaranteed minimum.
    if (texture > 0) limits.maxTextureSize = texture;
    if (groups > 0) limits.maxComputeGroupsX = groups;
    if (storage > 0) limits.maxStorageBlockBytes = storage;
    return limits;
}

Status checkTextureSize(const DeviceLimits& limits, std::int64_t width, std::int64_t height,
                        std::string_view what) {
    if (width <= limits.maxTextureSize && height <= limits.maxTextureSize) return Status::success();
    return Error{cat(what, ": ", width, " x ", height, " pixels; this GPU's textures are at most ",
                     limits.maxTextureSize, " a side (GL_MAX_TEXTURE_SIZE)")};
}

Status checkStorageBlock(const DeviceLimits& limits, std::uint64_t count, std::uint64_t bytesEach,
                         std::string_view what) {
    // Compared as a quotient, so that no product overflows.
    const auto capacity = std::uint64_t(std::max<std::int64_t>(limits.maxStorageBlockBytes, 0));
    if (bytesEach == 0 || count <= capacity / bytesEach) return Status::success();
    return Error{cat(what, ": ", count, " x ", bytesEach, " bytes; this GPU's storage blocks hold at most ",
                     capacity, " bytes (GL_MAX_SHADER_STORAGE_BLOCK_SIZE)")};
}

}  // namespace fx::gl
