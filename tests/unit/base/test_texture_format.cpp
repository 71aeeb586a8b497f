#include <gtest/gtest.h>

#include "base/texture_format.hpp"

namespace fx {
namespace {

TEST(TextureFormat, NamesFollowTheEnumOrder) {
    EXPECT_EQ(toString(TextureFormat::RGBA8), "RGBA8");
    EXPECT_EQ(toString(TextureFormat::SRGB8_ALPHA8), "SRGB8_ALPHA8");
    EXPECT_EQ(toString(TextureFormat::RGBA16F), "RGBA16F");
    EXPECT_EQ(toString(TextureFormat::R11F_G11F_B10F), "R11F_G11F_B10F");
    EXPECT_EQ(toString(TextureFormat::RGB32F), "RGB32F");
    EXPECT_EQ(toString(TextureFormat::Depth24Stencil8), "Depth24Stencil8");
}

TEST(TextureFormat, BytesAndChannels) {
    EXPECT_EQ(bytesPerTexel(TextureFormat::RGBA8), 4);
    EXPECT_EQ(bytesPerTexel(TextureFormat::RGBA16F), 8);
    EXPECT_EQ(bytesPerTexel(TextureFormat::RGBA32F), 16);
    EXPECT_EQ(bytesPerTexel(TextureFormat::R11F_G11F_B10F), 4);
    EXPECT_EQ(bytesPerTexel(TextureFormat::RG16F), 4);
    EXPECT_EQ(bytesPerTexel(TextureFormat::R16F), 2);
    EXPECT_EQ(bytesPerTexel(TextureFormat::R8), 1);
    EXPECT_EQ(bytesPerTexel(TextureFormat::RGB32F), 12);
    EXPECT_EQ(bytesPerTexel(TextureFormat::Depth32F), 4);
    EXPECT_EQ(channelCount(TextureFormat::R11F_G11F_B10F), 3);
    EXPECT_EQ(channelCount(TextureFormat::RG16F), 2);
    EXPECT_EQ(channelCount(TextureFormat::Depth24Stencil8), 2);
}

TEST(TextureFormat, RenderabilityDecidesWhatAPassMayWrite) {
    EXPECT_TRUE(isColorRenderable(TextureFormat::RGBA16F));
    EXPECT_TRUE(isColorRenderable(TextureFormat::SRGB8_ALPHA8));
    EXPECT_FALSE(isColorRenderable(TextureFormat::RGB32F));
    EXPECT_FALSE(isColorRenderable(TextureFormat::Depth32F));
    EXPECT_TRUE(isDepth(TextureFormat::Depth24));
    EXPECT_TRUE(isDepth(TextureFormat::Depth24Stencil8));
    EXPECT_TRUE(hasStencil(TextureFormat::Depth24Stencil8));
    EXPECT_FALSE(isDepth(TextureFormat::R32F));
    EXPECT_TRUE(isFloat(TextureFormat::Depth32F));
    EXPECT_FALSE(isFloat(TextureFormat::Depth24));
    EXPECT_FALSE(isFloat(TextureFormat::RGBA8));
    EXPECT_TRUE(isFloat(TextureFormat::R11F_G11F_B10F));
    EXPECT_FALSE(isStorageCompatible(TextureFormat::SRGB8_ALPHA8));
    EXPECT_TRUE(isStorageCompatible(TextureFormat::RGBA16F));
}

TEST(TextureFormat, HowTheInspectorShowsAFormat) {
    EXPECT_TRUE(isSrgb(TextureFormat::SRGB8_ALPHA8));
    EXPECT_FALSE(isSrgb(TextureFormat::RGBA8));
    // Whole 255ths: 8-bit normalised colour, sRGB included (it stores them; sampling decodes).
    EXPECT_TRUE(isUnorm8(TextureFormat::RGBA8));
    EXPECT_TRUE(isUnorm8(TextureFormat::R8));
    EXPECT_TRUE(isUnorm8(TextureFormat::SRGB8_ALPHA8));
    EXPECT_FALSE(isUnorm8(TextureFormat::RGBA16F));
    EXPECT_FALSE(isUnorm8(TextureFormat::Depth24));
    EXPECT_FALSE(isUnorm8(TextureFormat::R11F_G11F_B10F));
}

TEST(TextureFormat, OneSpellingPerFormatAndNoNameTwice) {
    for (int i = 0; i < kTextureFormatCount; ++i) {
        for (int j = i + 1; j < kTextureFormatCount; ++j) {
            EXPECT_NE(toString(static_cast<TextureFormat>(i)), toString(static_cast<TextureFormat>(j)));
        }
    }
    EXPECT_EQ(toString(TextureFormat::Depth32F), "Depth32F");
    EXPECT_EQ(toString(TextureFormat::Depth24), "Depth24");
}

TEST(TextureFormat, EveryFormatIsEitherColourOrDepthRenderableExceptRGB32F) {
    for (int i = 0; i < kTextureFormatCount; ++i) {
        auto format = static_cast<TextureFormat>(i);
        bool renderable = isColorRenderable(format) || isDepth(format);
        EXPECT_EQ(renderable, format != TextureFormat::RGB32F) << toString(format);
        EXPECT_FALSE(isColorRenderable(format) && isDepth(format)) << toString(format);
        EXPECT_GT(bytesPerTexel(format), 0) << toString(format);
    }
}

}  // namespace
}  // namespace fx
