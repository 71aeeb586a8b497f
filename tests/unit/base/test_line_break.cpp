// Lines broken by Unicode's rules (ICU, Japanese rules): English at words, numbers never split, a
// number with its unit, no Japanese line starting with a small kana or a closing mark, no lone
// character or number on a title's last line.
#include <gtest/gtest.h>

#include "base/line_break.hpp"

namespace fx {
namespace {

// One unit per character (code point): a monospaced font where a kanji is as wide as a letter.
float characters(std::string_view s) {
    float n = 0;
    for (char c : s) n += (static_cast<unsigned char>(c) & 0xC0) != 0x80 ? 1.0f : 0.0f;
    return n;
}

std::vector<std::string> pieces(std::string_view text) {
    std::vector<std::string> out;
    for (std::string_view p : lineBreakPieces(text)) out.emplace_back(p);
    return out;
}

TEST(LineBreak, PiecesGiveTheTextBack) {
    for (std::string_view text : {"two words  here", "a 明るい b", "", "\xE6\x98 broken \xFF bytes",
                                  "ホタル（約 900）は、1/4 サイズ"}) {
        std::string joined;
        for (std::string_view p : lineBreakPieces(text)) joined += p;
        EXPECT_EQ(joined, text);
    }
    EXPECT_EQ(pieces("two words  here"), (std::vector<std::string>{"two ", "words  ", "here"}));
}

TEST(LineBreak, EnglishWrapsAtWordsAndNeverInsideANumber) {
    // The fact that broke as "b + 0." / "0000" in the overlay.
    const std::vector<std::string> lines = wrapLines("bloom = b + 0.0000 (the threshold)", 12, characters);
    for (const std::string& line : lines) {
        EXPECT_NE(line.back(), '.') << line;
        EXPECT_LE(characters(line), 12.0f) << line;
    }
    EXPECT_EQ(lines, (std::vector<std::string>{"bloom = b +", "0.0000 (the", "threshold)"}));
    // A fraction stays whole: lesson 09's "With 1/F = 1/P + 1/I" broke as "1/" / "F".
    for (const std::string& line :
         wrapLines("this is it. With 1/F = 1/P + 1/I (I: the distance)", 19, characters))
        EXPECT_NE(line.back(), '/') << line;
    // Sizes and ratios stay whole: "1280x720", "1/4".
    for (const std::string& line : wrapLines("a window of 1280x720 at 1/4 size", 10, characters))
        EXPECT_TRUE(line.find("1280x720") != std::string::npos || line.find("1280") == std::string::npos)
            << line;
}

TEST(LineBreak, ANumberStaysWithItsUnit) {
    EXPECT_EQ(wrapLines("the frame took 16 ms here", 16, characters),
              (std::vector<std::string>{"the frame took", "16 ms here"}));
    EXPECT_EQ(wrapLines("ライトは 1000 個です", 6, characters),
              (std::vector<std::string>{"ライトは", "1000 個", "です"}));
    // A number before a word that is not its unit may break from it.
    EXPECT_EQ(wrapLines("count 16 samples", 9, characters),
              (std::vector<std::string>{"count 16", "samples"}));
}

TEST(LineBreak, NoJapaneseLineStartsWithASmallKanaOrAClosingMark) {
    const std::string text = "ショットは「ちょっと」明るい。ホタル（約 900）は、バッファの外です。";
    for (float width = 3; width <= 12; ++width) {
        for (const std::string& line : wrapLines(text, width, characters)) {
            for (std::string_view forbidden : {"ョ", "ょ", "っ", "ッ", "ァ", "ー", "。", "、", "」", "）"})
                EXPECT_NE(line.rfind(forbidden, 0), 0u) << "width " << width << ": " << line;
        }
    }
}

TEST(LineBreak, ATitleNeverEndsOnALoneCharacterOrNumber) {
    // Lesson 06's Japanese title broke as "…に足し込" / "る" in the lesson window; a title ending in
    // a number as "…レベル" / "8".
    std::vector<std::string> lines = wrapLines("縮小バッファを順に足し込む", 12, characters);
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_GE(characters(lines.back()), 2.0f) << lines.back();
    EXPECT_EQ(lines, (std::vector<std::string>{"縮小バッファを順に足し", "込む"}));
    lines = wrapLines("ステップごとのレベル 8", 10, characters);
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_EQ(lines.back(), "ル 8");
    lines = wrapLines("A title that ends in 8", 20, characters);
    EXPECT_EQ(lines.back(), "in 8");
    // One line stays one line; a text of one piece is not broken.
    EXPECT_EQ(wrapLines("短い", 12, characters), (std::vector<std::string>{"短い"}));
    EXPECT_EQ(wrapLines("", 12, characters), (std::vector<std::string>{}));
}

}  // namespace
}  // namespace fx
