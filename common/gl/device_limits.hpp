#pragma once
// The sizes this GL device allows, asked once per context: what every size that grows with a scene
// (particles, images, joints) is checked against before anything is allocated, so that a large scene
// gets a message or a documented clamp instead of GL_INVALID_VALUE (docs/reliability.md, "Budgets").
#include <cstdint>
#include <string_view>

#include "base/result.hpp"

namespace fx::gl {

struct DeviceLimits {
    std::int64_t maxTextureSize = 16384;          // GL_MAX_TEXTURE_SIZE: either side of a 2D texture
    std::int64_t maxComputeGroupsX = 65535;       // GL_MAX_COMPUTE_WORK_GROUP_COUNT[0]
    std::int64_t maxStorageBlockBytes = 1 << 24;  // GL_MAX_SHADER_STORAGE_BLOCK_SIZE
};

// Queries the current context. The defaults above are GL 4.5's guaranteed minimums; a query that gives
// nothing keeps them.
DeviceLimits queryDeviceLimits();

// Whether an image of width x height fits a texture on this device: the refusal names `what` (a file),
// its size and the limit ("crate.png: 20000 x 16 pixels; this GPU's textures are at most 16384 a side").
// Whether `count` elements of `bytesEach` bytes fit one shader storage block (a skin's joint matrices);
// the refusal names `what`, the total and the limit.
Status checkStorageBlock(const DeviceLimits& limits, std::uint64_t count, std::uint64_t bytesEach,
                         std::string_view what);

Status checkTextureSize(const DeviceLimits& limits, std::int64_t width, std::int64_t height,
                        std::string_view what);

}  // namespace fx::gl
