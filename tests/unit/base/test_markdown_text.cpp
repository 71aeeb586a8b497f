// The markdown a step's text uses, read by md4c (CommonMark with GitHub's tables), as the overlay and
// the handout draw it.
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
    // CommonMark: stars between words pair up as emphasis, so a product in the text is escaped or
    // written as code; an unclosed mark stays as it is.
    EXPECT_EQ(styles(parseSpans("T\\*J and (T\\*J)\\*p cost `64` **open")),
              "[T*J and (T*J)*p cost ][C:64][ **open]");
    EXPECT_EQ(styles(parseSpans("T*J and (T*J)*p")), "[T][I:J and (T][J)*p]");
    // Bold drops the marks inside it: it is one colour.
    EXPECT_EQ(styles(parseSpans("**Seed `000`'s bloom.**")), "[B:Seed 000's bloom.]");
}

TEST(Markdown, ManyOpenBracketsAreReadInOnePass) {
    // Each "[" used to search the rest of the text for "](": four million of them (a lesson.md may be 64
    // MiB) took hours. md4c reads them in time linear in the text (a million here: under a second),
    // and the link after them still reads as a link.
    const std::string many(1'000'000, '[');
    auto spans = parseSpans(many + "[a](x.md) ![pic](p.png)");
    ASSERT_EQ(spans.size(), 2u);
    EXPECT_EQ(spans[0].text, many + "a ");
    EXPECT_EQ(spans[1].text, "pic");
    // Many "[" each with a long label that holds another "[" before the one link.
    std::string labels;
    for (int i = 0; i < 20000; ++i) labels += "[" + std::string(200, 'a');
    // Pictures that never close: each used to search the rest for ")".
    std::string pictures;
    for (int i = 0; i < 250'000; ++i) pictures += "![a](";
    EXPECT_EQ(styles(parseSpans(pictures)), "[" + pictures + "]");
    std::string read = "b " + labels;
    read.erase(read.rfind('['), 1);  // the last "[" opens the link; its label is read as text
    EXPECT_EQ(styles(parseSpans("[b](y) " + labels + "](z)")), "[" + read + "]");
}

TEST(Markdown, APictureWhoseAltTextHoldsBrackets) {
    // Lesson 10 step 3's picture: the alt text quotes an interval, the target has parentheses.
    EXPECT_EQ(styles(parseSpans(
                  "![Step 3: where the sum leaves [0, 1] (red above 1); right, RGBA8](<../x (1).png>) "
                  "after")),
              "[P:Step 3: where the sum leaves [0, 1] (red above 1); right, RGBA8][ after]");
    EXPECT_EQ(styles(parseSpans("see [the [1] table](t.md)")), "[see the [1] table]");
    EXPECT_EQ(parseSpans("![a [0, 1]](<../x (1).png>)").front().target, "../x (1).png");
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

TEST(Markdown, ReadsAsCommonMark) {
    // Bold holds code and line breaks as one bold span (lesson 09's hard cases).
    EXPECT_EQ(styles(parseBlocks("**Field of view near 0 and near\n180°**: kept, `x`").front().spans),
              "[B:Field of view near 0 and near 180°][: kept, ][C:x]");
    EXPECT_EQ(styles(parseSpans("**bold `code` bold**")), "[B:bold code bold]");
    // A line that starts with "+ " starts a list, as in any CommonMark reader (lesson 08 wraps its
    // formula so that no line does).
    auto blocks = parseBlocks("The factor `x 0.5\n+ 0.5` rises.");
    ASSERT_EQ(blocks.size(), 2u);
    EXPECT_EQ(blocks[1].kind, BlockKind::ListItem);
    EXPECT_EQ(parseBlocks("The factor `x 0.5 +\n0.5` rises.").size(), 1u);
    // Raw HTML is shown as the text it is; entities read as their characters.
    EXPECT_EQ(styles(parseSpans("<b>x</b> &amp; &#x41; &#66; &unknown;")), "[<b>x</b> & A B &unknown;]");
    // Numbered lists keep their numbers, loose items their text; a nested list is deeper.
    blocks = parseBlocks("3. a\n\n4. b\n   - c\n");
    ASSERT_EQ(blocks.size(), 3u);
    EXPECT_EQ(blocks[0].marker, "3.");
    EXPECT_EQ(blocks[1].marker, "4.");
    EXPECT_EQ(styles(blocks[1].spans), "[b]");
    EXPECT_EQ(blocks[2].indent, 1);
    // A row of bars without a separator line is no table.
    blocks = parseBlocks("| a | b |\n| c | d |\n");
    ASSERT_EQ(blocks.size(), 1u);
    EXPECT_TRUE(blocks[0].cells.empty());
}

TEST(Markdown, EmptyTextHasNoBlocks) {
    EXPECT_TRUE(parseBlocks("").empty());
    EXPECT_TRUE(parseBlocks("\n\n  \n").empty());
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
