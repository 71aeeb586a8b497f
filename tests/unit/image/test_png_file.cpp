#include <gtest/gtest.h>

#include <filesystem>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wall"
#pragma GCC diagnostic ignored "-Wextra"
#include <stb/stb_image.h>
#pragma GCC diagnostic pop

#include "base/file_io.hpp"
#include "image/png_file.hpp"
#include "temp_folder.hpp"

namespace fx {
namespace {

ByteImage gradient(int width, int height, int channels) {
    ByteImage image = makeByteImage(width, height, channels);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < channels; ++c)
                image.texel(x, y, c) = static_cast<std::uint8_t>((x * 37 + y * 11 + c * 60) & 255);
    return image;
}

TEST(PngFile, RgbaRoundTripIsExact) {
    test::TempFolder folder;
    const ByteImage image = gradient(17, 9, 4);
    ASSERT_TRUE(writePng(folder / "a.png", image).ok());
    auto read = readPng(folder / "a.png");
    ASSERT_TRUE(read.ok()) << read.error();
    EXPECT_EQ(read->width, 17);
    EXPECT_EQ(read->height, 9);
    EXPECT_EQ(read->channels, 4);
    EXPECT_EQ(read->texels, image.texels);
    EXPECT_EQ(folder.entries(), std::vector<std::string>{"a.png"});  // no temporary file left
}

TEST(PngFile, FewerChannelsComeBackAsRgba) {
    test::TempFolder folder;
    const ByteImage grey = gradient(5, 4, 1);
    ASSERT_TRUE(writePng(folder / "grey.png", grey).ok());
    auto read = readPng(folder / "grey.png");
    ASSERT_TRUE(read.ok()) << read.error();
    EXPECT_EQ(read->texels, toRgba(grey).texels);

    const ByteImage rgb = gradient(3, 6, 3);
    ASSERT_TRUE(writePng(folder / "rgb.png", rgb).ok());
    auto readRgb = readPng(folder / "rgb.png");
    ASSERT_TRUE(readRgb.ok()) << readRgb.error();
    EXPECT_EQ(readRgb->texels, toRgba(rgb).texels);
}

TEST(PngFile, FileRowsAreTopDown) {
    // The bottom row (y = 0) is red, the rest black. Decoded straight by stb_image, which returns
    // the file's rows in file order (top first), the red row must come last.
    ByteImage image = makeByteImage(2, 3, 3);
    image.texel(0, 0, 0) = image.texel(1, 0, 0) = 255;
    auto bytes = encodePng(image);
    ASSERT_TRUE(bytes.ok()) << bytes.error();
    int width = 0, height = 0, channels = 0;
    unsigned char* decoded =
        stbi_load_from_memory(reinterpret_cast<const unsigned char*>(bytes->data()),
                              static_cast<int>(bytes->size()), &width, &height, &channels, 3);
    ASSERT_NE(decoded, nullptr);
    ASSERT_EQ(width, 2);
    ASSERT_EQ(height, 3);
    EXPECT_EQ(decoded[0], 0);            // first row in the file: the top, black
    EXPECT_EQ(decoded[2 * 2 * 3], 255);  // last row in the file: the bottom, red
    stbi_image_free(decoded);
}

TEST(PngFile, EmptyOrInconsistentImagesAreRefused) {
    test::TempFolder folder;
    EXPECT_FALSE(writePng(folder / "empty.png", ByteImage{}).ok());
    ByteImage broken = makeByteImage(4, 4, 3);
    broken.texels.resize(5);
    Status status = writePng(folder / "broken.png", broken);
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.error().find("broken.png"), std::string::npos);
    EXPECT_TRUE(folder.entries().empty());
}

TEST(PngFile, ReadErrorsNameThePathAndReason) {
    test::TempFolder folder;
    auto missing = readPng(folder / "missing.png");
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().find("missing.png"), std::string::npos);

    ASSERT_TRUE(writeFileAtomically(folder / "text.png", std::string_view("this is not a picture")).ok());
    auto garbage = readPng(folder / "text.png");
    ASSERT_FALSE(garbage.ok());
    EXPECT_NE(garbage.error().find("text.png"), std::string::npos);
    EXPECT_NE(garbage.error().find("not a readable PNG"), std::string::npos);
}

TEST(PngFile, UnwritableFolderLeavesNothingBehind) {
    test::TempFolder folder;
    const std::filesystem::path locked = folder / "locked";
    std::filesystem::create_directories(locked);
    std::filesystem::permissions(locked,
                                 std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
    const Status status = writePng(locked / "out.png", gradient(4, 4, 4));
    const bool canWriteAnyway = status.ok();  // root ignores folder permissions
    std::filesystem::permissions(locked, std::filesystem::perms::owner_all);
    if (canWriteAnyway) GTEST_SKIP() << "running with permission to write into read-only folders (root?)";
    EXPECT_NE(status.error().find("out.png"), std::string::npos);
    EXPECT_TRUE(std::filesystem::is_empty(locked));
}

TEST(PngFile, FolderNobodyCanWriteLeavesNothingBehind) {
    // /proc refuses new files even to root, so this runs wherever the chmod test above is skipped.
    const std::filesystem::path target = "/proc/fx_image_unwritable_test.png";
    if (!std::filesystem::is_directory("/proc")) GTEST_SKIP() << "no /proc on this system";
    const Status status = writePng(target, gradient(4, 4, 4));
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.error().find(target.string()), std::string::npos);
    for (const auto& entry : std::filesystem::directory_iterator("/proc"))
        EXPECT_EQ(entry.path().filename().string().find("fx_image_unwritable_test"), std::string::npos);
}

TEST(PngFile, ParentThatIsAFileLeavesNothingBehind) {
    test::TempFolder folder;
    ASSERT_TRUE(writePng(folder / "file.png", gradient(2, 2, 4)).ok());
    const Status status = writePng(folder / "file.png" / "inner.png", gradient(2, 2, 4));
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.error().find("inner.png"), std::string::npos);
    EXPECT_EQ(folder.entries(), std::vector<std::string>{"file.png"});
}

TEST(PngFile, FailedReplaceKeepsNothingBesideTheTarget) {
    // Works even as root: the target path is a non-empty folder, so the final rename must fail.
    test::TempFolder folder;
    std::filesystem::create_directories(folder / "out.png" / "child");
    const Status status = writePng(folder / "out.png", gradient(4, 4, 4));
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.error().find("out.png"), std::string::npos);
    EXPECT_EQ(folder.entries(), std::vector<std::string>{"out.png"});
    EXPECT_TRUE(std::filesystem::is_directory(folder / "out.png"));
}

}  // namespace
}  // namespace fx

// A small file that decodes to a huge picture is refused from its header (docs/reliability.md, "Budgets").
TEST(PngFile, AnImageOverThePixelLimitIsRefusedBeforeItIsDecoded) {
    // 65 KB of PNG, one black grey row past 8192 x 8192: 268 MB once decoded to RGBA. Made by Python's
    // zlib (IHDR 8192 x 8193, grey, 8 bits; IDAT the rows compressed; CRCs right), so stb reads it whole.
    auto decoded =
        fx::readPng(std::filesystem::path(FXLAB_TEST_DATA) / "images" / "over_pixel_limit_8192x8193.png");
    ASSERT_FALSE(decoded.ok());
    EXPECT_NE(
        decoded.error().find("over_pixel_limit_8192x8193.png: 8192 x 8193 pixels is over the limit for an "
                             "image (67108864 pixels"),
        std::string::npos)
        << decoded.error();
    // The boundary itself.
    EXPECT_TRUE(fx::checkImagePixels(8192, 8192, "at.png").ok());
    EXPECT_TRUE(fx::checkImagePixels(67108864, 1, "line.png").ok());
    EXPECT_FALSE(fx::checkImagePixels(8192, 8193, "over.png").ok());
    EXPECT_FALSE(fx::checkImagePixels(67108865, 1, "line.png").ok());
}
