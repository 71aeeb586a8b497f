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
    // The cut keeps whole UTF-8 characters.
    w = wrapAtWords("\xC3\xA9\xC3\xA9\xC3\xA9\xC3\xA9\xC3\xA9", 7, width);  // one word of five "é"
    ASSERT_EQ(w.lines.size(), 1u);
    EXPECT_EQ(w.lines[0], "\xC3\xA9\xC3\xA9...");
    // Japanese has no spaces: it wraps between characters instead of being cut (it was "あ...").
    w = wrapAtWords("\xE3\x81\x82\xE3\x81\x84\xE3\x81\x86\xE3\x81\x88", 7, width);
    EXPECT_EQ(w.lines, (std::vector<std::string>{"\xE3\x81\x82\xE3\x81\x84", "\xE3\x81\x86\xE3\x81\x88"}));
    EXPECT_FALSE(w.elided);
    EXPECT_TRUE(wrapAtWords("", 10, width).lines.empty());
}

TEST(WordWrap, NumbersAndJapaneseBreakByUnicodesRules) {
    // A number's dot is no place to break a name at; Japanese breaks between characters, never
    // before a small kana.
    WrappedText w = wrapAtWords("threshold 0.25 used", 10, width);
    for (const std::string& line : w.lines) EXPECT_NE(line, "threshold 0.") << line;
    EXPECT_EQ(w.lines, (std::vector<std::string>{"threshold", "0.25 used"}));
    w = wrapAtWords("\xE3\x82\xB7\xE3\x83\xA7\xE3\x83\x83\xE3\x83\x88", 3, width);  // ショット
    for (const std::string& line : w.lines)
        EXPECT_NE(line.rfind("\xE3\x83\xA7", 0), 0u);  // no line starts with ョ
}

TEST(WordWrap, OneLineCutsWithDotsAndSaysSo) {
    WrappedText w = oneLine("bloom.down[0] (+=), bloom.up[1]", 16, width);
    ASSERT_EQ(w.lines.size(), 1u);
    EXPECT_TRUE(w.elided);
    EXPECT_EQ(w.lines[0], "bloom.down[0]...");
    w = oneLine("scene", 16, width);
    EXPECT_EQ(w.lines, (std::vector<std::string>{"scene"}));
    EXPECT_FALSE(w.elided);
    EXPECT_TRUE(oneLine("", 16, width).lines.empty());
}

}  // namespace
}  // namespace fx
