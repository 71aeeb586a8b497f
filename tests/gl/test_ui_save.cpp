// Saving from the inspector: PFM keeps the exact stored floats (alpha in a second file), PNG is the
// picture the view shows at one pixel per texel, and a save that cannot complete leaves no file.
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

#include <unistd.h>

#include "gl/readback.hpp"
#include "gl/texture.hpp"
#include "gl_test.hpp"
#include "image/pfm_file.hpp"
#include "image/png_file.hpp"
#include "image/view_transform.hpp"
#include "ui/texture_saver.hpp"

using namespace fx;
namespace fs = std::filesystem;

namespace {

bool sameBits(float a, float b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

// One folder per test and process, so parallel runs cannot race; removed when the test ends.
struct TempFolder {
    fs::path path;
    explicit TempFolder(const std::string& name)
        : path(fs::temp_directory_path() / ("fxlab-ui-save-" + name + "-" + std::to_string(::getpid()))) {
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TempFolder() {
        std::error_code ignored;
        fs::remove_all(path, ignored);
    }
};

gl::Texture awkwardTexture() {
    auto t = gl::Texture::create2D(TextureFormat::RGBA32F, 5, 3, 2, "test.save");
    const float inf = std::numeric_limits<float>::infinity();
    std::vector<float> v(5 * 3 * 4);
    for (std::size_t i = 0; i < v.size(); ++i) v[i] = float(i) * 0.37f - 3.0f;  // negative to above 1
    v[0] = std::nanf("");
    v[5] = inf;
    v[10] = -inf;
    v[13] = 1e-40f;
    v[20] = 65504.0f * 4.0f;
    for (std::size_t i = 3; i < v.size(); i += 4) v[i] = float(i) / 64.0f;  // alpha, kept separately
    glTextureSubImage2D(t.name(), 0, 0, 0, 5, 3, GL_RGBA, GL_FLOAT, v.data());
    return t;
}

}  // namespace

class UiSave : public GlTest {};

TEST_F(UiSave, PfmHoldsTheExactFloats) {
    auto t = awkwardTexture();
    FloatImage stored = gl::readTexture(t);
    TempFolder folder("pfm");
    const fs::path& dir = folder.path;
    fs::path path = inspectorFilePath(dir, "scene.hdr[2]", 0, ".pfm");
    EXPECT_EQ(path.filename(), "scene.hdr_2_-mip0.pfm");
    ASSERT_TRUE(saveExactPfm(textureSource(t), 0, path).ok());

    auto rgb = readPfm(path);
    ASSERT_TRUE(rgb.ok()) << rgb.error();
    ASSERT_EQ(rgb->width, 5);
    ASSERT_EQ(rgb->height, 3);
    ASSERT_EQ(rgb->channels, 3);
    auto alpha = readPfm(dir / "scene.hdr_2_-mip0.alpha.pfm");
    ASSERT_TRUE(alpha.ok()) << alpha.error();
    ASSERT_EQ(alpha->channels, 1);
    for (int y = 0; y < 3; ++y) {
        for (int x = 0; x < 5; ++x) {
            for (int c = 0; c < 3; ++c) {
                EXPECT_TRUE(sameBits(rgb->texel(x, y, c), stored.texel(x, y, c)))
                    << x << "," << y << "," << c;
            }
            EXPECT_TRUE(sameBits(alpha->texel(x, y, 0), stored.texel(x, y, 3))) << x << "," << y;
        }
    }
}

TEST_F(UiSave, PfmOfAnotherLevelHasThatLevelsSize) {
    auto t = awkwardTexture();
    TempFolder folder("level");
    fs::path path = folder.path / "level1.pfm";
    ASSERT_TRUE(saveExactPfm(textureSource(t), 1, path).ok());
    auto image = readPfm(path);
    ASSERT_TRUE(image.ok());
    EXPECT_EQ(image->width, 2);
    EXPECT_EQ(image->height, 1);
}

TEST_F(UiSave, PngIsTheViewAtOnePixelPerTexelAndMatchesTheCaptures) {
    auto t = gl::Texture::create2D(TextureFormat::RGBA16F, 6, 4, 1, "test.save png");
    std::vector<float> v(6 * 4 * 4);
    for (std::size_t i = 0; i < v.size(); ++i) v[i] = (i % 4 == 3) ? 1.0f : float(i % 11) * 0.13f - 0.2f;
    v[4] = std::nanf("");
    glTextureSubImage2D(t.name(), 0, 0, 0, 6, 4, GL_RGBA, GL_FLOAT, v.data());
    TextureDisplay display;
    ASSERT_TRUE(display.ok()) << display.error();
    ViewSettings s = defaultViewSettings(t.spec());  // float colour: linear -> sRGB, range [0, 1]
    TempFolder folder("png");
    fs::path path = folder.path / "view.png";
    ASSERT_TRUE(saveViewPng(display, textureSource(t), s, path).ok());
    auto png = readPng(path);
    ASSERT_TRUE(png.ok()) << png.error();
    // The captures' CPU transform (image/view_transform) gives the same bytes, NaN magenta included.
    ByteImage expected = toDisplay(gl::readTexture(t), ViewTransform::LinearToSrgb);
    ASSERT_EQ(png->width, 6);
    ASSERT_EQ(png->height, 4);
    for (int y = 0; y < 4; ++y) {
        for (int x = 0; x < 6; ++x) {
            for (int c = 0; c < 3; ++c) {
                EXPECT_NEAR(png->texel(x, y, c), expected.texel(x, y, c), 1) << x << "," << y << "," << c;
            }
        }
    }
    EXPECT_EQ(png->texel(1, 0, 0), 255);  // the NaN texel
    EXPECT_EQ(png->texel(1, 0, 1), 0);
}

TEST_F(UiSave, AFailedSaveLeavesNoFile) {
    auto t = awkwardTexture();
    TempFolder folder("fail");
    const fs::path& dir = folder.path;
    std::ofstream(dir / "not-a-folder") << "x";
    fs::path path = dir / "not-a-folder" / "t.pfm";
    EXPECT_FALSE(saveExactPfm(textureSource(t), 0, path).ok());
    EXPECT_FALSE(fs::exists(path));
    EXPECT_FALSE(saveExactPfm(TextureSource{}, 0, dir / "dead.pfm").ok());
    EXPECT_FALSE(fs::exists(dir / "dead.pfm"));
    // Only the file we made by hand is in the folder: no temporary files left behind.
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}
