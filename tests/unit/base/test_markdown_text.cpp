// The markdown a step's text uses, as the overlay draws it.
#include <gtest/gtest.h>

#include "base/markdown_text.hpp"

namespace {

using namespace fx::markdown;

std::string styles(const std::vector<Span>& spans) {
    std::string out;
    for (const Span& s : spans) {
        const char* name = s.style == Style::Strong     ? "B"
                           : s.style == Style::Emphasis ? "I"
                           : s.style == Style::Code     ? "C"
                           : s.style == Style::Picture  ? "P"
                                                        : "";
        out += std::string("[") + name + (name[0] ? ":" : "") + s.text + "]";
    }
    return out;
}

TEST(Markdown, InlineStyles) {
    EXPECT_EQ(styles(parseSpans("a **bold** and `T*J*p` and *soft* [link](x.md) ![pic](p.png) \\*x")),
              "[a ][B:bold][ and ][C:T*J*p][ and ][I:soft][ link ][P:pic][ *x]");
    // A star inside a product is not emphasis; an unclosed mark stays as it is.
    EXPECT_EQ(styles(parseSpans("T*J and (T*J)*p cost `64` **open")),
              "[T*J and (T*J)*p cost ][C:64][ **open]");
    // Bold drops the marks inside it: it is one colour.
    EXPECT_EQ(styles(parseSpans("**Seed `000`'s bloom.**")), "[B:Seed 000's bloom.]");
}

TEST(Markdown, ManyOpenBracketsAreReadInOnePass) {
    // Each "[" used to search the rest of the text for "](": four million of them (a lesson.md may be 64
    // MiB) took hours. Now one pass, and the link after them still reads as a link.
    const std::string many(4'000'000, '[');
    auto spans = parseSpans(many + "[a](x.md) ![pic](p.png)");
    ASSERT_EQ(spans.size(), 2u);
    EXPECT_EQ(spans[0].text, many + "a ");
    EXPECT_EQ(spans[1].text, "pic");
    // Many "[" each with a long label that holds another "[" before the one link.
    std::string labels;
    for (int i = 0; i < 20000; ++i) labels += "[" + std::string(200, 'a');
    // A million pictures that never close: each used to search the rest for ")".
    std::string pictures;
    for (int i = 0; i < 1'000'000; ++i) pictures += "![a](";
    EXPECT_EQ(styles(parseSpans(pictures)), "[" + pictures + "]");
    std::string read = "b " + labels;
    read.erase(read.rfind('['), 1);  // the last "[" opens the link; its label is read as text
    EXPECT_EQ(styles(parseSpans("[b](y) " + labels + "](z)")), "[" + read + "]");
}

TEST(Markdown, APictureWhoseAltTextHoldsBrackets) {
    // Lesson 10 step 3's picture: the alt text quotes an interval, the target has parentheses.
    EXPECT_EQ(
        styles(parseSpans("![Step 3: where the sum leaves [0, 1] (red above 1); right, RGBA8](../x (1).png) "
                          "after")),
        "[P:Step 3: where the sum leaves [0, 1] (red above 1); right, RGBA8][ after]");
    EXPECT_EQ(styles(parseSpans("see [the [1] table](t.md)")), "[see the [1] table]");
    // Unbalanced: left as text, never a crash or a lost tail.
    EXPECT_EQ(styles(parseSpans("![open [0, 1](p.png")), "[![open [0, 1](p.png]");
    EXPECT_EQ(styles(parseSpans("[a] (b)")), "[[a] (b)]");
}

TEST(Markdown, BlocksOfAStep) {
    auto blocks = parseBlocks(
        "First line\ncontinues.\n\n- one\n  more\n   - nested\n3. numbered\n\n```\ncode ──►\n  "
        "kept\n```\n### Sub\n"
        "| a | b |\n|---|---|\n| ![](x.png) | c |\n");
    ASSERT_EQ(blocks.size(), 8u);
    EXPECT_EQ(blocks[0].kind, BlockKind::Paragraph);
    EXPECT_EQ(styles(blocks[0].spans), "[First line continues.]");
    EXPECT_EQ(blocks[1].kind, BlockKind::ListItem);
    EXPECT_EQ(blocks[1].marker, "-");
    EXPECT_EQ(styles(blocks[1].spans), "[one more]");
    EXPECT_EQ(blocks[2].indent, 1);
    EXPECT_EQ(blocks[3].marker, "3.");
    EXPECT_EQ(blocks[4].kind, BlockKind::CodeBlock);
    EXPECT_EQ(blocks[4].spans[0].text, "code ──►\n  kept");
    EXPECT_EQ(blocks[5].kind, BlockKind::Heading);
    EXPECT_EQ(styles(blocks[5].spans), "[Sub]");
    EXPECT_EQ(styles(blocks[6].spans), "[a  |  b]");
    EXPECT_EQ(styles(blocks[7].spans), "[P:][  |  c]");
}

// What the handout needs beyond the overlay: a picture's file, and a table's cells and header row.
TEST(Markdown, PicturesKeepTheirFileAndTablesTheirCells) {
    auto spans = parseSpans("see ![Step 1: a](../../docs/images/x.png) and [text](y.md)");
    ASSERT_EQ(spans.size(), 3u);
    EXPECT_EQ(spans[1].style, Style::Picture);
    EXPECT_EQ(spans[1].target, "../../docs/images/x.png");
    EXPECT_EQ(spans[2].target, "");  // a link keeps its text only, as the overlay shows it

    auto blocks =
        parseBlocks("| a | `b` |  |\n|---|---|---|\n| ![](p.png) |  | c |\n| d | e | f |\n\nAfter.");
    ASSERT_EQ(blocks.size(), 4u);
    EXPECT_TRUE(blocks[0].tableHeader);
    EXPECT_FALSE(blocks[1].tableHeader);
    ASSERT_EQ(blocks[0].cells.size(), 3u);  // the empty cell stays: the columns line up
    EXPECT_EQ(styles(blocks[0].cells[1]), "[C:b]");
    EXPECT_TRUE(blocks[0].cells[2].empty());
    ASSERT_EQ(blocks[1].cells.size(), 3u);
    EXPECT_EQ(blocks[1].cells[0].front().target, "p.png");
    EXPECT_EQ(styles(blocks[2].cells[2]), "[f]");
    EXPECT_TRUE(blocks[3].cells.empty());
    // The overlay still reads each row as one line of text.
    EXPECT_EQ(styles(blocks[0].spans), "[a  |  ][C:b]");
}

TEST(Markdown, JapaneseLinesJoinWithoutASpace) {
    auto blocks = parseBlocks("大きい\nレベルに足し込みます。\nRGBA8 に\n書く。\nA\nB");
    ASSERT_EQ(blocks.size(), 1u);
    // Between Japanese and a Latin word the line break stays a space, as the text writes it inside a line.
    EXPECT_EQ(blocks[0].spans[0].text, "大きいレベルに足し込みます。 RGBA8 に書く。 A B");
}

TEST(Markdown, EmptyTextHasNoBlocks) {
    EXPECT_TRUE(parseBlocks("").empty());
    EXPECT_TRUE(parseBlocks("\n\n  \n").empty());
}

TEST(Markdown, BreakPiecesKeepSpacesWithWordsAndSplitJapanese) {
    std::vector<std::string_view> words = breakPieces("two words  here");
    ASSERT_EQ(words.size(), 3u);
    EXPECT_EQ(words[0], "two ");
    EXPECT_EQ(words[1], "words  ");
    EXPECT_EQ(words[2], "here");
    // Japanese: one character a piece, closing punctuation kept with the character before it;
    // a Latin word inside Japanese stays whole.
    std::vector<std::string_view> ja = breakPieces("明るい。RGBA8に");
    ASSERT_EQ(ja.size(), 5u);
    EXPECT_EQ(ja[0], "明");
    EXPECT_EQ(ja[2], "い。");
    EXPECT_EQ(ja[3], "RGBA8");
    EXPECT_EQ(ja[4], "に");
    std::string joined;
    for (auto p : breakPieces("a 明るい b")) joined += p;
    EXPECT_EQ(joined, "a 明るい b");
}

TEST(Markdown, DecodesUtf8AndReplacesBrokenBytes) {
    std::size_t length = 0;
    EXPECT_EQ(decodeUtf8("明", 0, length), U'明');
    EXPECT_EQ(length, 3u);
    EXPECT_EQ(decodeUtf8("\xE6\x98", 0, length), U'\uFFFD');  // cut short
    EXPECT_EQ(length, 1u);
    EXPECT_EQ(decodeUtf8("\xFF", 0, length), U'\uFFFD');
}

}  // namespace
