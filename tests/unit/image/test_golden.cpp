#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "image/golden.hpp"
#include "image/png_file.hpp"
#include "temp_folder.hpp"

namespace fx {
namespace {

// Sets FXLAB_UPDATE_GOLDEN for one test and restores what was there before.
class UpdateGoldenVariable {
public:
    explicit UpdateGoldenVariable(const char* value) {
        if (const char* old = std::getenv(kUpdateGoldenVariable)) previous_ = old, hadPrevious_ = true;
        if (value)
            ::setenv(kUpdateGoldenVariable, value, 1);
        else
            ::unsetenv(kUpdateGoldenVariable);
    }
    ~UpdateGoldenVariable() {
        if (hadPrevious_)
            ::setenv(kUpdateGoldenVariable, previous_.c_str(), 1);
        else
            ::unsetenv(kUpdateGoldenVariable);
    }
    UpdateGoldenVariable(const UpdateGoldenVariable&) = delete;
    UpdateGoldenVariable& operator=(const UpdateGoldenVariable&) = delete;

private:
    std::string previous_;
    bool hadPrevious_ = false;
};

ByteImage checkerboard() {
    ByteImage image = makeByteImage(16, 12, 4, 255);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < 3; ++c) image.texel(x, y, c) = ((x / 4 + y / 4) % 2) ? 220 : 30;
    return image;
}

const GoldenTolerance kTolerance{1.0, 8};

TEST(Golden, MatchingImagePasses) {
    UpdateGoldenVariable off(nullptr);
    test::TempFolder folder;
    ASSERT_TRUE(writePng(folder / "src" / "board.png", checkerboard()).ok());
    ByteImage actual = checkerboard();
    actual.texel(3, 3, 0) += 5;  // within the tolerance
    auto verdict = checkGolden(actual, folder / "src" / "board.png", kTolerance, folder / "out");
    ASSERT_TRUE(verdict.ok()) << verdict.error();
    EXPECT_TRUE(verdict->passed()) << verdict->message;
    EXPECT_EQ(verdict->outcome, GoldenOutcome::Match);
    ASSERT_TRUE(verdict->difference.has_value());
    EXPECT_EQ(verdict->difference->maxAbs, 5.0);
    EXPECT_FALSE(std::filesystem::exists(folder / "out"));  // nothing to look at
}

TEST(Golden, MismatchWritesActualAndDiffIntoTheOutputFolder) {
    UpdateGoldenVariable off(nullptr);
    test::TempFolder folder;
    ASSERT_TRUE(writePng(folder / "src" / "board.png", checkerboard()).ok());
    ByteImage actual = checkerboard();
    for (int x = 0; x < 16; ++x) actual.texel(x, 5, 1) = 128;  // a wrong row
    auto verdict = checkGolden(actual, folder / "src" / "board.png", kTolerance, folder / "out");
    ASSERT_TRUE(verdict.ok()) << verdict.error();
    EXPECT_FALSE(verdict->passed());
    EXPECT_EQ(verdict->outcome, GoldenOutcome::Mismatch);
    EXPECT_EQ(verdict->actualPath, folder / "out" / "board.actual.png");
    EXPECT_EQ(verdict->diffPath, folder / "out" / "board.diff.png");
    auto writtenActual = readPng(verdict->actualPath);
    ASSERT_TRUE(writtenActual.ok());
    EXPECT_EQ(writtenActual->texels, actual.texels);
    auto diff = readPng(verdict->diffPath);
    ASSERT_TRUE(diff.ok());
    EXPECT_GE(diff->texel(0, 5, 0), 128);                   // the wrong row is red
    EXPECT_EQ(diff->texel(0, 4, 1), diff->texel(0, 4, 0));  // the rest grey
    // The message names the measurements and the tolerance, and the golden file is untouched.
    EXPECT_NE(verdict->message.find("RMSE"), std::string::npos);
    EXPECT_NE(verdict->message.find("tolerance"), std::string::npos);
    EXPECT_NE(verdict->message.find("board.diff.png"), std::string::npos);
    auto golden = readPng(folder / "src" / "board.png");
    ASSERT_TRUE(golden.ok());
    EXPECT_EQ(golden->texels, checkerboard().texels);
}

TEST(Golden, DifferentSizeIsAMismatchWithTheActualPicture) {
    UpdateGoldenVariable off(nullptr);
    test::TempFolder folder;
    ASSERT_TRUE(writePng(folder / "board.png", checkerboard()).ok());
    auto verdict = checkGolden(makeByteImage(8, 8, 4), folder / "board.png", kTolerance, folder / "out");
    ASSERT_TRUE(verdict.ok()) << verdict.error();
    EXPECT_EQ(verdict->outcome, GoldenOutcome::Mismatch);
    EXPECT_NE(verdict->message.find("16x12"), std::string::npos);
    EXPECT_NE(verdict->message.find("8x8"), std::string::npos);
    EXPECT_TRUE(std::filesystem::exists(folder / "out" / "board.actual.png"));
}

TEST(Golden, MissingGoldenFailsAndSaysHowToCreateIt) {
    UpdateGoldenVariable off(nullptr);
    test::TempFolder folder;
    auto verdict = checkGolden(checkerboard(), folder / "none.png", kTolerance, folder / "out");
    ASSERT_TRUE(verdict.ok()) << verdict.error();
    EXPECT_FALSE(verdict->passed());
    EXPECT_EQ(verdict->outcome, GoldenOutcome::Missing);
    EXPECT_NE(verdict->message.find("FXLAB_UPDATE_GOLDEN=1"), std::string::npos);
    EXPECT_NE(verdict->message.find("none.png"), std::string::npos);
    EXPECT_FALSE(std::filesystem::exists(folder / "none.png"));
}

TEST(Golden, UpdateModeWritesTheGoldenAndPasses) {
    UpdateGoldenVariable on("1");
    test::TempFolder folder;
    ByteImage old = makeByteImage(16, 12, 4, 9);
    ASSERT_TRUE(writePng(folder / "board.png", old).ok());
    auto verdict = checkGolden(checkerboard(), folder / "board.png", kTolerance, folder / "out");
    ASSERT_TRUE(verdict.ok()) << verdict.error();
    EXPECT_TRUE(verdict->passed());
    EXPECT_EQ(verdict->outcome, GoldenOutcome::Updated);
    EXPECT_NE(verdict->message.find("updated"), std::string::npos);
    auto golden = readPng(folder / "board.png");
    ASSERT_TRUE(golden.ok());
    EXPECT_EQ(golden->texels, checkerboard().texels);
    EXPECT_EQ(folder.entries(), std::vector<std::string>{"board.png"});
}

TEST(Golden, OnlyTheValueOneTurnsUpdatingOn) {
    UpdateGoldenVariable zero("0");
    EXPECT_FALSE(goldenUpdateRequested());
}

TEST(Golden, UnreadableGoldenIsAnError) {
    UpdateGoldenVariable off(nullptr);
    test::TempFolder folder;
    std::filesystem::create_directories(folder.path());
    ASSERT_TRUE(writePng(folder / "ok.png", checkerboard()).ok());
    std::filesystem::resize_file(folder / "ok.png", 20);  // cut short
    auto verdict = checkGolden(checkerboard(), folder / "ok.png", kTolerance, folder / "out");
    ASSERT_FALSE(verdict.ok());
    EXPECT_NE(verdict.error().find("ok.png"), std::string::npos);
}

}  // namespace
}  // namespace fx
