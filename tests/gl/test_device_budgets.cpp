// Sizes that grow with a scene, checked against this device before anything is allocated
// (docs/reliability.md, "Budgets"): an image a side longer than GL_MAX_TEXTURE_SIZE is refused with
// the file and the limit (a texture falls back to white, a sprite or a cloud's density stops the run
// with the message), never a GL_INVALID_VALUE; one at the limit uploads.
#include <unistd.h>
#include <cstdio>
#include <filesystem>

#include "base/file_io.hpp"
#include "effects/scene/material_textures.hpp"
#include "gl/device_limits.hpp"
#include "gl/texture_image.hpp"
#include "gl_test.hpp"
#include "image/png_file.hpp"

using namespace fx;
namespace fs = std::filesystem;

class DeviceBudgets : public GlTest {
protected:
    fs::path folder = fs::temp_directory_path() / ("fx_device_budgets_" + std::to_string(::getpid()));
    void TearDown() override {
        fs::remove_all(folder);
        GlTest::TearDown();
    }
    // A one-row PNG `width` texels wide.
    fs::path strip(int width) {
        fs::path file = folder / ("strip-" + std::to_string(width) + ".png");
        EXPECT_TRUE(writePng(file, makeByteImage(width, 1, 4, 200)).ok());
        return file;
    }
};

TEST_F(DeviceBudgets, TheLimitsAreTheDevicesOwn) {
    gl::DeviceLimits limits = gl::queryDeviceLimits();
    GLint texture = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &texture);
    EXPECT_EQ(limits.maxTextureSize, texture);
    EXPECT_GE(limits.maxComputeGroupsX, 65535);
    EXPECT_GE(limits.maxStorageBlockBytes, std::int64_t(1) << 24);
    std::printf(
        "this device: GL_MAX_TEXTURE_SIZE %lld, GL_MAX_COMPUTE_WORK_GROUP_COUNT[0] %lld, "
        "GL_MAX_SHADER_STORAGE_BLOCK_SIZE %lld\n",
        static_cast<long long>(limits.maxTextureSize), static_cast<long long>(limits.maxComputeGroupsX),
        static_cast<long long>(limits.maxStorageBlockBytes));
}

TEST_F(DeviceBudgets, AnImageWiderThanTheDevicesTexturesIsRefusedNotUploaded) {
    const int limit = int(gl::queryDeviceLimits().maxTextureSize);
    fs::path over = strip(limit + 1);
    auto refused = gl::readTextureImage(over);
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().find(over.string() + ": " + std::to_string(limit + 1) +
                                   " x 1 pixels; this GPU's "
                                   "textures are at most " +
                                   std::to_string(limit) + " a side"),
              std::string::npos)
        << refused.error();
    // A material's texture falls back to white, with no GL error (the fixture fails on one).
    MaterialTextures textures;
    EXPECT_EQ(textures.file(over), textures.white());
    // At the limit: uploaded.
    GLuint at = textures.file(strip(limit));
    ASSERT_NE(at, textures.white());
    GLint width = 0;
    glGetTextureLevelParameteriv(at, 0, GL_TEXTURE_WIDTH, &width);
    EXPECT_EQ(width, limit);
}
