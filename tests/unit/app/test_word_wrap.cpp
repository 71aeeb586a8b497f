// Names in a narrow column: wrapped after spaces and the dots of a name, never inside a word; a word
// too wide alone is cut with "..." and said to be.
#include <gtest/gtest.h>

#include "ui/word_wrap.hpp"

namespace fx {
namespace {

// One unit per byte: a monospaced font.
float width(std::string_view s) {
    return float(s.size());
}

TEST(WordWrap, BreaksAtWordsAndTheDotsOfANameNeverInsideAWord) {
    WrappedText w = wrapAtWords("particles.pool view", 12, width);
    EXPECT_EQ(w.lines, (std::vector<std::string>{"particles.", "pool view"}));
    EXPECT_FALSE(w.elided);
    w = wrapAtWords("state inherited / left", 10, width);
    EXPECT_EQ(w.lines, (std::vector<std::string>{"state", "inherited", "/ left"}));
    w = wrapAtWords("scene", 40, width);
    EXPECT_EQ(w.lines, (std::vector<std::string>{"scene"}));
}

TEST(WordWrap, AWordWiderThanTheColumnIsCutAndSaysSo) {
    WrappedText w = wrapAtWords("deferred lighting_tiled_compute", 12, width);
    EXPECT_FALSE(w.elided) << "every word fits: lighting_ / tiled_ / compute";
    w = wrapAtWords("deferred lightingtiledcompute", 12, width);
    EXPECT_TRUE(w.elided);
    for (const std::string& line : w.lines) EXPECT_LE(line.size(), 12u) << line;
    EXPECT_EQ(w.lines, (std::vector<std::string>{"deferred", "lightingt..."}));
    // The cut keeps whole UTF-8 characters (lesson.ja.md names reach the overlay too).
    w = wrapAtWords("\xE3\x81\x82\xE3\x81\x84\xE3\x81\x86\xE3\x81\x88", 7, width);
    ASSERT_EQ(w.lines.size(), 1u);
    EXPECT_EQ(w.lines[0], "\xE3\x81\x82...");
    EXPECT_TRUE(wrapAtWords("", 10, width).lines.empty());
}

}  // namespace
}  // namespace fx
