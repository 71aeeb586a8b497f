#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>

#include "base/file_io.hpp"
#include "image/pfm_file.hpp"
#include "temp_folder.hpp"

namespace fx {
namespace {

std::uint32_t bitsOf(float v) {
    std::uint32_t bits = 0;
    std::memcpy(&bits, &v, sizeof bits);
    return bits;
}

float fromBits(std::uint32_t bits) {
    float v = 0.0f;
    std::memcpy(&v, &bits, sizeof v);
    return v;
}

// Values a hard-case capture can hold: every one must survive bit for bit.
std::vector<float> awkwardValues() {
    return {0.0f,
            -0.0f,
            1.0f,
            -2.5f,
            65504.0f,
            1e30f,
            std::numeric_limits<float>::infinity(),
            -std::numeric_limits<float>::infinity(),
            std::numeric_limits<float>::quiet_NaN(),
            fromBits(0xffc00123u),  // a negative NaN with a payload
            fromBits(0x7f800001u),  // a signalling NaN
            std::numeric_limits<float>::denorm_min(),
            -std::numeric_limits<float>::denorm_min() * 77.0f,
            std::numeric_limits<float>::min(),
            0.1f};
}

TEST(PfmFile, RgbRoundTripIsBitExact) {
    test::TempFolder folder;
    const std::vector<float> values = awkwardValues();
    FloatImage image = makeFloatImage(5, 3, 3);
    for (std::size_t i = 0; i < image.texels.size(); ++i) image.texels[i] = values[i % values.size()];
    ASSERT_TRUE(writePfm(folder / "a.pfm", image).ok());
    auto read = readPfm(folder / "a.pfm");
    ASSERT_TRUE(read.ok()) << read.error();
    ASSERT_EQ(read->width, 5);
    ASSERT_EQ(read->height, 3);
    ASSERT_EQ(read->channels, 3);
    for (std::size_t i = 0; i < image.texels.size(); ++i)
        EXPECT_EQ(bitsOf(read->texels[i]), bitsOf(image.texels[i])) << "value " << i;
    EXPECT_EQ(folder.entries(), std::vector<std::string>{"a.pfm"});
}

TEST(PfmFile, GreyRoundTripIsBitExact) {
    test::TempFolder folder;
    const std::vector<float> values = awkwardValues();
    FloatImage image = makeFloatImage(static_cast<int>(values.size()), 1, 1);
    image.texels = values;
    ASSERT_TRUE(writePfm(folder / "g.pfm", image).ok());
    auto read = readPfm(folder / "g.pfm");
    ASSERT_TRUE(read.ok()) << read.error();
    EXPECT_EQ(read->channels, 1);
    for (std::size_t i = 0; i < values.size(); ++i) EXPECT_EQ(bitsOf(read->texels[i]), bitsOf(values[i]));
}

TEST(PfmFile, HeaderAndRowOrderFollowTheFormat) {
    test::TempFolder folder;
    FloatImage image = makeFloatImage(2, 2, 1);
    image.texels = {1.0f, 2.0f, 3.0f, 4.0f};  // bottom row first, which is also the file's order
    ASSERT_TRUE(writePfm(folder / "h.pfm", image).ok());
    auto text = readTextFile(folder / "h.pfm");
    ASSERT_TRUE(text.ok());
    const std::string header = "Pf\n2 2\n-1.0\n";
    ASSERT_EQ(text->substr(0, header.size()), header);
    ASSERT_EQ(text->size(), header.size() + 16);
    float first = 0.0f;
    std::memcpy(&first, text->data() + header.size(), 4);  // the test machine is little-endian
    EXPECT_EQ(first, 1.0f);
}

TEST(PfmFile, AlphaIsDroppedAndTwoChannelsGetZeroBlue) {
    test::TempFolder folder;
    FloatImage rgba = makeFloatImage(1, 1, 4);
    rgba.texels = {0.1f, 0.2f, 0.3f, 0.4f};
    ASSERT_TRUE(writePfm(folder / "rgba.pfm", rgba).ok());
    auto read = readPfm(folder / "rgba.pfm");
    ASSERT_TRUE(read.ok());
    EXPECT_EQ(read->texels, (std::vector<float>{0.1f, 0.2f, 0.3f}));

    FloatImage rg = makeFloatImage(1, 1, 2);
    rg.texels = {0.5f, -0.5f};
    ASSERT_TRUE(writePfm(folder / "rg.pfm", rg).ok());
    auto readRg = readPfm(folder / "rg.pfm");
    ASSERT_TRUE(readRg.ok());
    EXPECT_EQ(readRg->texels, (std::vector<float>{0.5f, -0.5f, 0.0f}));
}

TEST(PfmFile, ReadsBigEndianFiles) {
    test::TempFolder folder;
    std::string file = "Pf\n1 1\n1.0\n";         // positive scale: big-endian
    file += std::string("\x3f\x80\x00\x00", 4);  // 1.0f
    ASSERT_TRUE(writeFileAtomically(folder / "be.pfm", std::string_view(file)).ok());
    auto read = readPfm(folder / "be.pfm");
    ASSERT_TRUE(read.ok()) << read.error();
    EXPECT_EQ(read->texels, std::vector<float>{1.0f});
}

TEST(PfmFile, BadFilesAreReportedWithPathAndReason) {
    test::TempFolder folder;
    const auto expectError = [&](const std::string& name, const std::string& content,
                                 const std::string& reason) {
        ASSERT_TRUE(writeFileAtomically(folder / name, std::string_view(content)).ok());
        auto read = readPfm(folder / name);
        ASSERT_FALSE(read.ok()) << name;
        EXPECT_NE(read.error().find(name), std::string::npos) << read.error();
        EXPECT_NE(read.error().find(reason), std::string::npos) << read.error();
    };
    expectError("magic.pfm", "P6\n1 1\n255\n...", "not a PFM");
    expectError("size.pfm", "PF\n0 4\n-1.0\n", "bad PFM size");
    expectError("scale.pfm", "PF\n1 1\nabc\n", "bad PFM scale");
    expectError("short.pfm", std::string("PF\n2 1\n-1.0\n") + std::string(12, '\0'), "truncated");
    auto missing = readPfm(folder / "missing.pfm");
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().find("missing.pfm"), std::string::npos);
}

TEST(PfmFile, EmptyImageIsRefused) {
    test::TempFolder folder;
    Status status = writePfm(folder / "e.pfm", FloatImage{});
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.error().find("e.pfm"), std::string::npos);
    EXPECT_TRUE(folder.entries().empty());
}

}  // namespace
}  // namespace fx
