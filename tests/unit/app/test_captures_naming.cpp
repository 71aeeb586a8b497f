// What the app writes and says it wrote: screenshots never replace earlier ones, and the capture
// message names only files that exist.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "app/capture.hpp"
#include "app/run_results.hpp"
#include "ui/pixel_probe.hpp"
#include "ui/texture_analysis.hpp"

namespace fs = std::filesystem;

TEST(Screenshots, NamesSayLessonAndStepAndNeverReplaceAnEarlierOne) {
    const fs::path dir = fs::temp_directory_path() / "fxlab-screenshot-test";
    fs::remove_all(dir);
    fs::create_directories(dir);
    auto first = fx::nextScreenshotPath(dir, "fxlab-05-radial-blur", 2);
    EXPECT_EQ(first.filename(), "fxlab-05-radial-blur-step2-001.png");
    std::ofstream(first) << "png";
    // The next session (a new process) finds the first one there and takes the next number.
    EXPECT_EQ(fx::nextScreenshotPath(dir, "fxlab-05-radial-blur", 2).filename(),
              "fxlab-05-radial-blur-step2-002.png");
    EXPECT_EQ(fx::nextScreenshotPath(dir, "fxlab-05-radial-blur", 3).filename(),
              "fxlab-05-radial-blur-step3-001.png");
    fs::remove_all(dir);
}

TEST(CaptureMessage, AnEmptyFrameDoesNotClaimAFinalImage) {
    const std::string empty = fx::capturesWrittenMessage("out/x", false, false, 0, true);
    EXPECT_EQ(empty.find("final.png written"), std::string::npos) << empty;
    EXPECT_NE(empty.find("nothing captured"), std::string::npos) << empty;
    EXPECT_NE(empty.find("0x0"), std::string::npos) << empty;
    const std::string textures = fx::capturesWrittenMessage("out/x", false, false, 3, true);
    EXPECT_NE(textures.find("no final.png"), std::string::npos) << textures;
    const std::string full = fx::capturesWrittenMessage("out/x", true, false, 1, false);
    EXPECT_EQ(full, "captures written to out/x/: final.png and 1 intermediate texture");
    const std::string closed = fx::capturesWrittenMessage("out/x", false, false, 0, false);
    EXPECT_EQ(closed.find("0x0"), std::string::npos) << closed;
    EXPECT_NE(closed.find("ended before its last frame"), std::string::npos) << closed;
}

TEST(ProbeText, ValuesShowEnoughDigitsToRead) {
    EXPECT_EQ(fx::exactFloatText(300.0f), "300");
    EXPECT_EQ(fx::exactFloatText(270.5f), "270.5");
    EXPECT_EQ(fx::exactFloatText(3000.0f), "3000");
    EXPECT_EQ(fx::exactFloatText(0.001f), "0.001");
    EXPECT_EQ(fx::exactFloatText(0.1f), "0.1");
    EXPECT_EQ(fx::exactFloatText(1e-5f), "1e-05");
    EXPECT_EQ(fx::exactFloatText(0.0f), "0");
}

TEST(FindSpecial, GoesToTheNextNanOrInfAndWrapsRound) {
    fx::FloatImage image = fx::makeFloatImage(4, 3, 4, 0.5f);
    image.texel(2, 1, 0) = std::numeric_limits<float>::quiet_NaN();
    image.texel(0, 2, 3) = std::numeric_limits<float>::infinity();
    std::int64_t count = 0;
    auto first = fx::nextSpecialTexel(image, -1, -1, &count);
    ASSERT_TRUE(first);
    EXPECT_EQ(count, 2);
    EXPECT_EQ(first->x, 2);
    EXPECT_EQ(first->y, 1);
    auto second = fx::nextSpecialTexel(image, first->x, first->y, nullptr);
    ASSERT_TRUE(second);
    EXPECT_EQ(second->x, 0);
    EXPECT_EQ(second->y, 2);
    auto wrapped = fx::nextSpecialTexel(image, second->x, second->y, nullptr);
    ASSERT_TRUE(wrapped);
    EXPECT_EQ(wrapped->x, 2);
    EXPECT_FALSE(fx::nextSpecialTexel(fx::makeFloatImage(2, 2, 1, 1.0f), -1, -1, &count));
    EXPECT_EQ(count, 0);
}
