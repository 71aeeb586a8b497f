// The checks of sizes against a device's limits at their boundary (no GL: the limits are given).
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "gl/device_limits.hpp"

TEST(DeviceLimits, ATextureAtTheLimitFitsAndOneTexelMoreIsRefusedByName) {
    const fx::gl::DeviceLimits limits{16384, 65535, std::int64_t(1) << 27};
    EXPECT_TRUE(fx::gl::checkTextureSize(limits, 16384, 16384, "a.png").ok());
    auto wide = fx::gl::checkTextureSize(limits, 16385, 1, "a.png");
    ASSERT_FALSE(wide.ok());
    EXPECT_EQ(wide.error(),
              "a.png: 16385 x 1 pixels; this GPU's textures are at most 16384 a side (GL_MAX_TEXTURE_SIZE)");
    EXPECT_FALSE(fx::gl::checkTextureSize(limits, 1, 16385, "a.png").ok());
}

TEST(DeviceLimits, AStorageBlockAtTheLimitFitsAndOneElementMoreIsRefused) {
    const fx::gl::DeviceLimits limits{16384, 65535, 64 * 1000};
    EXPECT_TRUE(fx::gl::checkStorageBlock(limits, 1000, 64, "skin").ok());
    auto over = fx::gl::checkStorageBlock(limits, 1001, 64, "skin");
    ASSERT_FALSE(over.ok());
    EXPECT_EQ(over.error(),
              "skin: 1001 x 64 bytes; this GPU's storage blocks hold at most 64000 bytes "
              "(GL_MAX_SHADER_STORAGE_BLOCK_SIZE)");
    // A count whose byte total would overflow 64 bits is refused, not wrapped round to a small number.
    EXPECT_FALSE(fx::gl::checkStorageBlock(limits, std::uint64_t(1) << 60, 64, "skin").ok());
}
