// Texture formats written and read back exactly: what every float test in the project relies on.
#include <cmath>
#include <limits>
#include <string>

#include "gl/gl_formats.hpp"
#include "gl/readback.hpp"
#include "gl/texture.hpp"
#include "gl_test.hpp"

using namespace fx;

namespace {

void upload(const gl::Texture& t, const std::vector<float>& rgba) {
    glTextureSubImage2D(t.name(), 0, 0, 0, t.width(), t.height(), GL_RGBA, GL_FLOAT, rgba.data());
}

}  // namespace

class TextureFormats : public GlTest {};

TEST_F(TextureFormats, Rgba32fRoundTripsEveryBitIncludingNanAndInf) {
    auto t = gl::Texture::create2D(TextureFormat::RGBA32F, 2, 2, 1, "test.rgba32f");
    const float inf = std::numeric_limits<float>::infinity();
    std::vector<float> values = {1.5f,          -2.25f, 65504.0f, 1e30f, 0.1f, 1e-40f, -inf, inf,
                                 std::nanf(""), 0.0f,   -0.0f,    3.0f,  7.0f, 8.0f,   9.0f, 1.0f};
    upload(t, values);
    FloatImage image = gl::readTexture(t);
    ASSERT_EQ(image.texels.size(), values.size());
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (std::isnan(values[i])) {
            EXPECT_TRUE(std::isnan(image.texels[i])) << i;
        } else {
            EXPECT_EQ(image.texels[i], values[i]) << i;
        }
    }
}

// (What a value above 65504 becomes on upload is the driver's choice: Mesa clamps it. Values a
// shader writes overflow to infinity; the bloom tests cover that case.)
TEST_F(TextureFormats, Rgba16fRoundsToHalfPrecision) {
    auto t = gl::Texture::create2D(TextureFormat::RGBA16F, 1, 1, 1, "test.rgba16f");
    upload(t, {1.0f / 3.0f, 65504.0f, 2049.0f, -0.5f});
    FloatImage image = gl::readTexture(t);
    EXPECT_NE(image.texels[0], 1.0f / 3.0f);                                // not representable in half
    EXPECT_NEAR(image.texels[0], 1.0f / 3.0f, 1.0f / 4096.0f);              // 11-bit significand
    EXPECT_EQ(image.texels[1], 65504.0f);                                   // the largest half float
    EXPECT_TRUE(image.texels[2] == 2048.0f || image.texels[2] == 2050.0f);  // spacing 2 above 2048
    EXPECT_EQ(image.texels[3], -0.5f);
}

TEST_F(TextureFormats, Rgba8StoresQuantisedValues) {
    auto t = gl::Texture::create2D(TextureFormat::RGBA8, 1, 1, 1, "test.rgba8");
    upload(t, {0.5f, 1.5f, -1.0f, 0.25f});
    FloatImage image = gl::readTexture(t);
    EXPECT_FLOAT_EQ(image.texels[0], 128.0f / 255.0f);
    EXPECT_FLOAT_EQ(image.texels[1], 1.0f);  // UNORM clamps: why an 8-bit scene loses the sun
    EXPECT_FLOAT_EQ(image.texels[2], 0.0f);
    EXPECT_FLOAT_EQ(image.texels[3], 64.0f / 255.0f);
}

TEST_F(TextureFormats, DepthReadsBackAsOneChannel) {
    auto t = gl::Texture::create2D(TextureFormat::Depth32F, 2, 1, 1, "test.depth");
    float depth[2] = {0.25f, 1.0f};
    glTextureSubImage2D(t.name(), 0, 0, 0, 2, 1, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
    FloatImage image = gl::readTexture(t);
    ASSERT_EQ(image.channels, 1);
    EXPECT_EQ(image.texels[0], 0.25f);
    EXPECT_EQ(image.texels[1], 1.0f);
}

TEST_F(TextureFormats, MipLevelsHaveHalvedSizesNeverBelowOne) {
    auto t = gl::Texture::create2D(TextureFormat::RGBA16F, 5, 3, 3, "test.mips");
    EXPECT_EQ(gl::readTexture(t, 1).width, 2);
    EXPECT_EQ(gl::readTexture(t, 1).height, 1);
    EXPECT_EQ(gl::readTexture(t, 2).width, 1);
    EXPECT_EQ(gl::readTexture(t, 2).height, 1);
}

// The facts table (base/texture_format.cpp) and the GL mapping (gl/gl_formats.cpp) are written
// apart; the driver says whether they agree: the internal format is the one asked for, and the
// channels GL stores and their bits match the table's channel count and bytes per texel.
TEST_F(TextureFormats, TheFactsTableAgreesWithWhatGlStores) {
    for (int i = 0; i < kTextureFormatCount; ++i) {
        const auto format = static_cast<TextureFormat>(i);
        const std::string name(toString(format));
        auto t = gl::Texture::create2D(format, 4, 4, 1, "test.format " + name);
        EXPECT_EQ(t.spec().format, format);
        GLint internal = 0;
        glGetTextureLevelParameteriv(t.name(), 0, GL_TEXTURE_INTERNAL_FORMAT, &internal);
        EXPECT_EQ(GLenum(internal), glInternalFormat(format)) << name;

        int channels = 0;
        int bits = 0;
        for (GLenum size : {GL_TEXTURE_RED_SIZE, GL_TEXTURE_GREEN_SIZE, GL_TEXTURE_BLUE_SIZE,
                            GL_TEXTURE_ALPHA_SIZE, GL_TEXTURE_DEPTH_SIZE, GL_TEXTURE_STENCIL_SIZE}) {
            GLint b = 0;
            glGetTextureLevelParameteriv(t.name(), 0, size, &b);
            channels += b > 0 ? 1 : 0;
            bits += b;
        }
        EXPECT_EQ(channels, channelCount(format)) << name;
        // Depth24 is padded to four bytes by drivers; the table counts what memory it costs.
        if (format == TextureFormat::Depth24) {
            EXPECT_EQ(bits, 24) << name;
        } else {
            EXPECT_EQ(bits, bytesPerTexel(format) * 8) << name;
        }
        GLint depthBits = 0;
        glGetTextureLevelParameteriv(t.name(), 0, GL_TEXTURE_DEPTH_SIZE, &depthBits);
        EXPECT_EQ(depthBits > 0, isDepth(format)) << name;
    }
}
