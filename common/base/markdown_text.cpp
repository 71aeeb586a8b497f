#include "base/markdown_text.hpp"

#include <md4c.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

// The blocks and spans are read by md4c (CommonMark with GitHub's tables); this file only turns its
// events into the few blocks the overlay and the handout draw.

namespace fx::markdown {
namespace {

// Characters between which a line may break with no space: kana, kanji, full-width forms.
bool isCjk(char32_t c) {
    return (c >= 0x2E80 && c <= 0x9FFF) || (c >= 0xF900 && c <= 0xFAFF) || (c >= 0xFF00 && c <= 0xFFEF);
}

char32_t lastCodePoint(std::string_view s) {
    if (s.empty()) return 0;
    std::size_t last = s.size() - 1;
    while (last > 0 && (static_cast<unsigned char>(s[last]) & 0xC0) == 0x80) --last;
    std::size_t length = 0;
    return decodeUtf8(s, last, length);
}

void appendUtf8(std::string& out, char32_t c) {
    if (c < 0x80) {
        out += char(c);
    } else if (c < 0x800) {
        out += char(0xC0 | (c >> 6));
        out += char(0x80 | (c & 0x3F));
    } else if (c < 0x10000) {
        out += char(0xE0 | (c >> 12));
        out += char(0x80 | ((c >> 6) & 0x3F));
        out += char(0x80 | (c & 0x3F));
    } else {
        out += char(0xF0 | (c >> 18));
        out += char(0x80 | ((c >> 12) & 0x3F));
        out += char(0x80 | ((c >> 6) & 0x3F));
        out += char(0x80 | (c & 0x3F));
    }
}

// An entity as text: the numeric ones and the few named ones a lesson might write; any other stays
// as written (md4c passes entities through verbatim).
std::string entityText(std::string_view entity) {
    std::string out;
    if (entity.size() > 3 && entity[1] == '#') {
        const bool hex = entity[2] == 'x' || entity[2] == 'X';
        char32_t c = 0;
        for (std::size_t i = hex ? 3 : 2; i + 1 < entity.size(); ++i) {
            const char d = entity[i];
            const int v = d >= '0' && d <= '9'          ? d - '0'
                          : hex && d >= 'a' && d <= 'f' ? d - 'a' + 10
                          : hex && d >= 'A' && d <= 'F' ? d - 'A' + 10
                                                        : -1;
            if (v < 0 || c > 0x10FFFF) return std::string(entity);
            c = c * (hex ? 16 : 10) + char32_t(v);
        }
        if (c == 0 || c > 0x10FFFF || (c >= 0xD800 && c <= 0xDFFF)) c = U'\uFFFD';
        appendUtf8(out, c);
        return out;
    }
    static const std::pair<std::string_view, char32_t> named[] = {
        {"&amp;", U'&'},       {"&lt;", U'<'},    {"&gt;", U'>'},   {"&quot;", U'"'}, {"&apos;", U'\''},
        {"&nbsp;", U'\u00A0'}, {"&times;", U'×'}, {"&rarr;", U'→'}, {"&le;", U'≤'},   {"&ge;", U'≥'}};
    for (const auto& [name, c] : named) {
        if (entity == name) {
            appendUtf8(out, c);
            return out;
        }
    }
    return std::string(entity);
}

std::string attributeText(const MD_ATTRIBUTE& a) {
    std::string out;
    for (unsigned i = 0; a.substr_offsets[i] < a.size; ++i) {
        const std::string_view part(a.text + a.substr_offsets[i],
                                    a.substr_offsets[i + 1] - a.substr_offsets[i]);
        if (a.substr_types[i] == MD_TEXT_ENTITY)
            out += entityText(part);
        else if (a.substr_types[i] == MD_TEXT_NULLCHAR)
            out += "\uFFFD";
        else
            out += part;
    }
    return out;
}

// Turns md4c's events into Blocks. Lists: each item is a block (its marker and nesting depth); a
// paragraph inside an item after a nested list is a paragraph of its own. Tables: each row is a block
// with its cells.
class BlockBuilder {
public:
    std::vector<Block> blocks;

    void enterBlock(MD_BLOCKTYPE type, void* detail) {
        switch (type) {
            case MD_BLOCK_UL: {
                lists_.push_back({false, 0, 0});
                closeCurrent();
                break;
            }
            case MD_BLOCK_OL: {
                lists_.push_back({true, static_cast<MD_BLOCK_OL_DETAIL*>(detail)->start, 0});
                closeCurrent();
                break;
            }
            case MD_BLOCK_LI: {
                closeCurrent();
                List& list = lists_.back();
                begin(BlockKind::ListItem);
                current_.marker = list.ordered ? std::to_string(list.start + list.items) + "." : "-";
                current_.indent = std::min(int(lists_.size()) - 1, 3);
                ++list.items;
                break;
            }
            case MD_BLOCK_H:
                closeCurrent();
                begin(BlockKind::Heading);
                break;
            case MD_BLOCK_CODE:
                closeCurrent();
                begin(BlockKind::CodeBlock);
                break;
            case MD_BLOCK_P:
            case MD_BLOCK_HTML:
                // A paragraph of a list item is the item's text (a loose list's items hold one each).
                if (open_ && current_.kind == BlockKind::ListItem && !itemHasText_) break;
                closeCurrent();
                begin(BlockKind::Paragraph);
                break;
            case MD_BLOCK_THEAD:
                inHead_ = true;
                break;
            case MD_BLOCK_TBODY:
                inHead_ = false;
                break;
            case MD_BLOCK_TR:
                closeCurrent();
                begin(BlockKind::Paragraph);
                current_.tableHeader = inHead_;
                inRow_ = true;
                break;
            case MD_BLOCK_TH:
            case MD_BLOCK_TD:
                current_.cells.emplace_back();
                break;
            case MD_BLOCK_TABLE:
                closeCurrent();
                break;
            default:
                break;
        }
    }

    void leaveBlock(MD_BLOCKTYPE type) {
        switch (type) {
            case MD_BLOCK_UL:
            case MD_BLOCK_OL:
                closeCurrent();
                lists_.pop_back();
                break;
            case MD_BLOCK_LI:
            case MD_BLOCK_H:
            case MD_BLOCK_TR:
                inRow_ = false;
                closeCurrent();
                break;
            case MD_BLOCK_CODE:
                if (!current_.spans.empty()) {
                    std::string& code = current_.spans.front().text;
                    while (!code.empty() && code.back() == '\n') code.pop_back();
                }
                closeCurrent();
                break;
            case MD_BLOCK_P:
            case MD_BLOCK_HTML:
                if (open_ && current_.kind == BlockKind::ListItem)
                    itemHasText_ = true;
                else
                    closeCurrent();
                break;
            default:
                break;
        }
    }

    void enterSpan(MD_SPANTYPE type, void* detail) {
        const Style parent = styles_.empty() ? Style::Plain : styles_.back();
        Style style = parent;
        // Inside bold everything is bold (one colour); inside a picture everything is its alt text.
        if (parent != Style::Strong && parent != Style::Picture) {
            if (type == MD_SPAN_STRONG) style = Style::Strong;
            if (type == MD_SPAN_EM) style = Style::Emphasis;
            if (type == MD_SPAN_CODE) style = Style::Code;
            if (type == MD_SPAN_IMG) {
                style = Style::Picture;
                if (!open_) begin(BlockKind::Paragraph);
                softBreak(Style::Plain, {});
                target().push_back(
                    {Style::Picture, {}, attributeText(static_cast<MD_SPAN_IMG_DETAIL*>(detail)->src)});
                boundary_ = false;  // the alt text that follows is this picture's
            } else if (style != parent || type == MD_SPAN_CODE) {
                boundary_ = true;
            }
        }
        styles_.push_back(style);
    }

    void leaveSpan(MD_SPANTYPE) {
        const Style left = styles_.empty() ? Style::Plain : styles_.back();
        if (!styles_.empty()) styles_.pop_back();
        const Style parent = styles_.empty() ? Style::Plain : styles_.back();
        if (parent != Style::Strong && parent != Style::Picture && (left != parent || left == Style::Code))
            boundary_ = true;
    }

    void text(MD_TEXTTYPE type, std::string_view text) {
        if (!open_) begin(BlockKind::Paragraph);
        const Style style = current_.kind == BlockKind::CodeBlock ? Style::Plain
                            : styles_.empty()                     ? Style::Plain
                                                                  : styles_.back();
        switch (type) {
            case MD_TEXT_SOFTBR:
                // Japanese broken over two lines joins with no space between the lines; words do.
                pendingSoftBreak_ = true;
                return;
            case MD_TEXT_BR:
                add(style, " ");
                return;
            case MD_TEXT_NULLCHAR:
                add(style, "\uFFFD");
                return;
            case MD_TEXT_ENTITY:
                add(style, entityText(text));
                return;
            default:
                add(style, text);
                return;
        }
    }

    void finish() { closeCurrent(); }

private:
    struct List {
        bool ordered;
        unsigned start;
        unsigned items;
    };

    void begin(BlockKind kind) {
        current_ = Block{};
        current_.kind = kind;
        open_ = true;
        itemHasText_ = false;
        pendingSoftBreak_ = false;
        boundary_ = false;
    }

    std::vector<Span>& target() {
        return inRow_ && !current_.cells.empty() ? current_.cells.back() : current_.spans;
    }

    void add(Style style, std::string_view text) {
        if (!open_) begin(BlockKind::Paragraph);
        softBreak(style, text);
        append(target(), style, text);
    }

    // A line break inside a paragraph is a space in the text's style, except between two Japanese
    // characters: Japanese broken over two lines joins with no space, words do.
    void softBreak(Style style, std::string_view next) {
        if (!pendingSoftBreak_) return;
        pendingSoftBreak_ = false;
        std::vector<Span>& spans = target();
        std::size_t length = 0;
        const bool joins = !spans.empty() && !next.empty() && isCjk(lastCodePoint(spans.back().text)) &&
                           isCjk(decodeUtf8(next, 0, length));
        if (joins) return;
        const bool wasBoundary = boundary_;
        const bool sameStyle = !spans.empty() && spans.back().style == style;
        if (sameStyle) boundary_ = false;
        append(spans, sameStyle ? style : Style::Plain, " ");
        boundary_ = wasBoundary && !sameStyle;
    }

    // Text joins the span before it when nothing began or ended between them (one code span's pieces,
    // a picture's alt text); plain text always joins plain text (a link's label reads as text).
    void append(std::vector<Span>& spans, Style style, std::string_view text) {
        const bool joins =
            !spans.empty() && spans.back().style == style && (style == Style::Plain || !boundary_);
        boundary_ = false;
        if (joins)
            spans.back().text += text;
        else
            spans.push_back({style, std::string(text)});
    }

    void closeCurrent() {
        if (open_) {
            if (current_.cells.empty()) {
                const bool empty = current_.spans.empty();
                if (!empty || current_.kind == BlockKind::ListItem || current_.kind == BlockKind::CodeBlock)
                    blocks.push_back(std::move(current_));
            } else {
                // The overlay's plain reading of a row: its cells joined, empty cells left out.
                for (const std::vector<Span>& cell : current_.cells) {
                    if (cell.empty()) continue;
                    if (!current_.spans.empty()) append(current_.spans, Style::Plain, "  |  ");
                    for (const Span& s : cell) {
                        boundary_ = true;
                        append(current_.spans, s.style, s.text);
                        if (s.style == Style::Picture) current_.spans.back().target = s.target;
                    }
                }
                blocks.push_back(std::move(current_));
            }
        }
        open_ = false;
        current_ = Block{};
    }

    Block current_;
    bool open_ = false, itemHasText_ = false, inHead_ = false, inRow_ = false;
    bool pendingSoftBreak_ = false;
    bool boundary_ = false;  // a span began or ended since the last text
    std::vector<List> lists_;
    std::vector<Style> styles_;
};

int onEnterBlock(MD_BLOCKTYPE type, void* detail, void* user) {
    static_cast<BlockBuilder*>(user)->enterBlock(type, detail);
    return 0;
}
int onLeaveBlock(MD_BLOCKTYPE type, void*, void* user) {
    static_cast<BlockBuilder*>(user)->leaveBlock(type);
    return 0;
}
int onEnterSpan(MD_SPANTYPE type, void* detail, void* user) {
    static_cast<BlockBuilder*>(user)->enterSpan(type, detail);
    return 0;
}
int onLeaveSpan(MD_SPANTYPE type, void*, void* user) {
    static_cast<BlockBuilder*>(user)->leaveSpan(type);
    return 0;
}
int onText(MD_TEXTTYPE type, const MD_CHAR* text, MD_SIZE size, void* user) {
    static_cast<BlockBuilder*>(user)->text(type, std::string_view(text, size));
    return 0;
}

}  // namespace

char32_t decodeUtf8(std::string_view text, std::size_t i, std::size_t& length) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
    const unsigned char b0 = byte(i);
    length = 1;
    if (b0 < 0x80) return b0;
    int extra = (b0 & 0xE0) == 0xC0 ? 1 : (b0 & 0xF0) == 0xE0 ? 2 : (b0 & 0xF8) == 0xF0 ? 3 : -1;
    if (extra < 0 || i + std::size_t(extra) >= text.size()) return U'\uFFFD';
    char32_t c = b0 & (0x3F >> extra);
    for (int k = 1; k <= extra; ++k) {
        const unsigned char b = byte(i + std::size_t(k));
        if ((b & 0xC0) != 0x80) return U'\uFFFD';
        c = (c << 6) | (b & 0x3F);
    }
    length = std::size_t(extra) + 1;
    return c;
}

std::vector<Block> parseBlocks(std::string_view text) {
    BlockBuilder builder;
    if (text.size() >= std::numeric_limits<MD_SIZE>::max()) return {};  // lesson files are far smaller
    MD_PARSER parser{};
    parser.abi_version = 0;
    // GitHub's tables; raw HTML is shown as the text it is (a lesson's text has none on purpose), and
    // indented lines continue a paragraph or a list item rather than starting a code block.
    parser.flags = MD_FLAG_TABLES | MD_FLAG_NOHTML | MD_FLAG_NOINDENTEDCODEBLOCKS;
    parser.enter_block = onEnterBlock;
    parser.leave_block = onLeaveBlock;
    parser.enter_span = onEnterSpan;
    parser.leave_span = onLeaveSpan;
    parser.text = onText;
    md_parse(text.data(), MD_SIZE(text.size()), &parser, &builder);
    builder.finish();
    return builder.blocks;
}

std::vector<Span> parseSpans(std::string_view text) {
    std::vector<Span> spans;
    for (const Block& b : parseBlocks(text)) {
        if (!spans.empty()) spans.push_back({Style::Plain, " "});
        for (const Span& s : b.spans) {
            if (s.style == Style::Plain && !spans.empty() && spans.back().style == Style::Plain)
                spans.back().text += s.text;
            else
                spans.push_back(s);
        }
    }
    return spans;
}

}  // namespace fx::markdown
