#pragma once
// A lesson's step text, read by md4c (CommonMark with GitHub's tables) into the few blocks the overlay
// (ui/markdown_view) and the handout (app/handout_html) draw, so both read lesson.md through one
// parser: paragraphs, bullet and numbered lists, ``` code blocks, headings, table rows, and inside
// text **bold**, *emphasis*, `code`, [links](url) (their text) and ![pictures](file) (their alt
// text). Raw HTML is shown as the text it is. GL-free: the tests check the parse.
#include <string>
#include <string_view>
#include <vector>

namespace fx::markdown {

enum class Style { Plain, Strong, Emphasis, Code, Picture };

struct Span {
    Style style = Style::Plain;
    std::string text;
    std::string target = {};  // a picture: its file, as written between the parentheses
};

enum class BlockKind { Paragraph, ListItem, Heading, CodeBlock };

struct Block {
    BlockKind kind = BlockKind::Paragraph;
    std::string marker;       // list items: "-" or "3."
    int indent = 0;           // list nesting, 0 for the outermost
    std::vector<Span> spans;  // a code block: one Plain span, its lines joined with '\n'
    // A table row (a Paragraph whose spans hold its cells joined by "  |  "): each cell's spans, empty
    // cells included, and whether the row is a header (the row above a "|---|" line).
    std::vector<std::vector<Span>> cells = {};
    bool tableHeader = false;
};

std::vector<Block> parseBlocks(std::string_view text);
// The spans of a text's blocks in one run (a heading or one paragraph's worth of text).
std::vector<Span> parseSpans(std::string_view text);

// The code point at text[i] (UTF-8), and how many bytes it takes; a broken byte reads as U+FFFD.
char32_t decodeUtf8(std::string_view text, std::size_t i, std::size_t& length);

}  // namespace fx::markdown
