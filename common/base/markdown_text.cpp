#include "base/markdown_text.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

namespace fx::markdown {
namespace {

std::string_view trimmedLeft(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    return s;
}

std::string_view trimmed(std::string_view s) {
    s = trimmedLeft(s);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
    return s;
}

bool startsWith(std::string_view s, std::string_view prefix) {
    return s.substr(0, prefix.size()) == prefix;
}

// "- x", "* x" or "12. x": the marker, and the text after it; empty marker when not a list item.
std::string_view listMarker(std::string_view line, std::string_view& rest) {
    if ((startsWith(line, "- ") || startsWith(line, "* "))) {
        rest = line.substr(2);
        return line.substr(0, 1);
    }
    std::size_t digits = 0;
    while (digits < line.size() && std::isdigit(static_cast<unsigned char>(line[digits]))) ++digits;
    if (digits > 0 && digits < 4 && line.substr(digits, 2) == ". ") {
        rest = line.substr(digits + 2);
        return line.substr(0, digits + 1);
    }
    return {};
}

bool isTableSeparator(std::string_view line) {
    return trimmed(line).find_first_not_of("|-: ") == std::string_view::npos;
}

// The cells of a table row "| a | b |", as written.
std::vector<std::string_view> tableCells(std::string_view line) {
    std::vector<std::string_view> cells;
    line = trimmed(line);
    if (startsWith(line, "|")) line.remove_prefix(1);
    if (!line.empty() && line.back() == '|') line.remove_suffix(1);
    std::size_t start = 0;
    while (start <= line.size()) {
        std::size_t bar = line.find('|', start);
        if (bar == std::string_view::npos) bar = line.size();
        cells.push_back(trimmed(line.substr(start, bar - start)));
        start = bar + 1;
    }
    return cells;
}

// A table row as text ("a  |  b"), its empty cells left out.
std::string tableRow(const std::vector<std::string_view>& cells) {
    std::string out;
    for (std::string_view cell : cells) {
        if (!cell.empty()) out += (out.empty() ? "" : "  |  ") + std::string(cell);
    }
    return out;
}

bool isClosingPunctuation(char32_t c) {
    switch (c) {
        case U'、':
        case U'。':
        case U'」':
        case U'』':
        case U'）':
        case U'，':
        case U'．':
        case U'！':
        case U'？':
        case U'：':
        case U'；':
        case U'ー':
        case U'ぁ':
        case U'ぃ':
        case U'ぅ':
        case U'ぇ':
        case U'ぉ':
        case U'っ':
        case U'ゃ':
        case U'ゅ':
        case U'ょ':
        case U'ァ':
        case U'ィ':
        case U'ゥ':
        case U'ェ':
        case U'ォ':
        case U'ッ':
        case U'ャ':
        case U'ュ':
        case U'ョ':
        case U'・':
            return true;
        default:
            return false;
    }
}

// Characters between which a line may break with no space: kana, kanji, full-width forms.
bool breaksAnywhere(char32_t c) {
    return (c >= 0x2E80 && c <= 0x9FFF) || (c >= 0xF900 && c <= 0xFAFF) || (c >= 0xFF00 && c <= 0xFFEF);
}

// Japanese text broken over two lines joins with no space between the lines; words do.
bool joinsWithoutSpace(std::string_view before, std::string_view after) {
    std::size_t last = before.size() - 1;
    while (last > 0 && (static_cast<unsigned char>(before[last]) & 0xC0) == 0x80) --last;
    std::size_t length = 0;
    return !after.empty() && breaksAnywhere(decodeUtf8(before, last, length)) &&
           breaksAnywhere(decodeUtf8(after, 0, length));
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

namespace {

// Every balanced pair of `open` and `close` in a text (nested pairs counted; an escaped bracket
// counts for nothing), found in one pass and looked up by where it opens. A search from every bracket
// would read the rest of the text each time: hours for a few megabytes of unclosed "[".
class BalancedPairs {
public:
    BalancedPairs(std::string_view text, char open, char close) {
        if (text.size() >= std::numeric_limits<std::uint32_t>::max()) return;  // files are far smaller
        std::vector<std::uint32_t> opened;
        for (std::size_t i = 0; i < text.size(); ++i) {
            if (text[i] == '\\' && i + 1 < text.size()) {
                ++i;
            } else if (text[i] == open) {
                opened.push_back(std::uint32_t(i));
            } else if (text[i] == close && !opened.empty()) {
                pairs_.push_back({opened.back(), std::uint32_t(i)});
                opened.pop_back();
            }
        }
        std::sort(pairs_.begin(), pairs_.end());
    }

    // The index of the `close` that balances the `open` at text[at], or npos.
    std::size_t closeOf(std::size_t at) const {
        const auto it =
            std::lower_bound(pairs_.begin(), pairs_.end(), std::pair{std::uint32_t(at), std::uint32_t(0)});
        return it != pairs_.end() && it->first == at ? it->second : std::string_view::npos;
    }

private:
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs_;
};

}  // namespace

std::vector<Span> parseSpans(std::string_view text) {
    std::vector<Span> spans;
    std::string plain;
    auto flush = [&] {
        if (!plain.empty()) spans.push_back({Style::Plain, plain});
        plain.clear();
    };
    auto emit = [&](Style style, std::string_view s) {
        flush();
        spans.push_back({style, std::string(s)});
    };
    // A link's or picture's label may hold brackets of its own ("[0, 1]"): its "]" is the one that
    // balances the "[", and the target's ")" the one that balances its "(".
    std::optional<BalancedPairs> brackets, parens;  // found on the first "[" (most text has none)
    std::size_t i = 0;
    while (i < text.size()) {
        const char c = text[i];
        const std::string_view rest = text.substr(i);
        if (c == '\\' && i + 1 < text.size() && std::ispunct(static_cast<unsigned char>(text[i + 1]))) {
            plain += text[i + 1];
            i += 2;
            continue;
        }
        if (c == '`') {
            std::size_t close = text.find('`', i + 1);
            if (close != std::string_view::npos) {
                emit(Style::Code, text.substr(i + 1, close - i - 1));
                i = close + 1;
                continue;
            }
        }
        if (startsWith(rest, "**")) {
            std::size_t close = text.find("**", i + 2);
            if (close != std::string_view::npos && close > i + 2) {
                // Inside bold, code and emphasis marks are dropped: bold is one colour.
                std::string inner;
                for (const Span& s : parseSpans(text.substr(i + 2, close - i - 2))) inner += s.text;
                emit(Style::Strong, inner);
                i = close + 2;
                continue;
            }
        }
        if (c == '*' && i + 1 < text.size() && text[i + 1] != ' ' && text[i + 1] != '*' &&
            (i == 0 || !std::isalnum(static_cast<unsigned char>(text[i - 1])))) {
            std::size_t close = text.find('*', i + 1);
            if (close != std::string_view::npos && text[close - 1] != ' ' &&
                (close + 1 >= text.size() || !std::isalnum(static_cast<unsigned char>(text[close + 1])))) {
                emit(Style::Emphasis, text.substr(i + 1, close - i - 1));
                i = close + 1;
                continue;
            }
        }
        if (c == '[' || startsWith(rest, "![")) {
            const bool picture = c == '!';
            std::size_t open = i + (picture ? 1 : 0);
            if (!brackets) {
                brackets.emplace(text, '[', ']');
                parens.emplace(text, '(', ')');
            }
            const std::size_t closeBracket = brackets->closeOf(open);
            const std::size_t closeParen = closeBracket != std::string_view::npos &&
                                                   closeBracket + 1 < text.size() &&
                                                   text[closeBracket + 1] == '('
                                               ? parens->closeOf(closeBracket + 1)
                                               : std::string_view::npos;
            if (closeParen != std::string_view::npos) {
                std::string_view label = text.substr(open + 1, closeBracket - open - 1);
                if (picture) {
                    emit(Style::Picture, label);
                    spans.back().target =
                        std::string(text.substr(closeBracket + 2, closeParen - closeBracket - 2));
                } else {
                    plain += label;
                }
                i = closeParen + 1;
                continue;
            }
        }
        plain += c;
        ++i;
    }
    flush();
    return spans;
}

std::vector<Block> parseBlocks(std::string_view text) {
    std::vector<Block> blocks;
    std::string pending;  // the text of the paragraph or list item being read
    Block current;
    bool open = false, inCode = false;
    std::string code;
    auto close = [&] {
        if (open) {
            current.spans = parseSpans(pending);
            if (!current.spans.empty() || current.kind == BlockKind::ListItem) blocks.push_back(current);
        }
        open = false;
        pending.clear();
        current = Block{};
    };
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        std::string_view raw = text.substr(start, end - start);
        start = end + 1;
        if (!raw.empty() && raw.back() == '\r') raw.remove_suffix(1);
        const std::string_view line = trimmedLeft(raw);
        const int spaces = int(raw.size() - line.size());
        if (startsWith(line, "```")) {
            if (inCode) {
                blocks.push_back({BlockKind::CodeBlock, {}, 0, {{Style::Plain, code}}});
                code.clear();
            } else {
                close();
            }
            inCode = !inCode;
            continue;
        }
        if (inCode) {
            code += (code.empty() ? "" : "\n") + std::string(raw);
            continue;
        }
        if (trimmed(line).empty()) {
            close();
            continue;
        }
        if (startsWith(line, "#")) {
            close();
            std::size_t hashes = line.find_first_not_of('#');
            current.kind = BlockKind::Heading;
            pending =
                std::string(trimmed(line.substr(hashes == std::string_view::npos ? line.size() : hashes)));
            open = true;
            close();
            continue;
        }
        if (startsWith(line, "|")) {
            close();
            if (isTableSeparator(line)) {
                // The row above a separator is the table's header.
                if (!blocks.empty() && !blocks.back().cells.empty()) blocks.back().tableHeader = true;
                continue;
            }
            const std::vector<std::string_view> cells = tableCells(line);
            std::string row = tableRow(cells);
            if (!row.empty()) {
                current.kind = BlockKind::Paragraph;
                for (std::string_view cell : cells) current.cells.push_back(parseSpans(cell));
                pending = row;
                open = true;
                close();
            }
            continue;
        }
        std::string_view rest;
        std::string_view marker = listMarker(line, rest);
        if (!marker.empty()) {
            close();
            current.kind = BlockKind::ListItem;
            current.marker = std::string(marker);
            current.indent = std::min(spaces / 2, 3);
            pending = std::string(trimmed(rest));
            open = true;
            continue;
        }
        std::string_view content = trimmed(startsWith(line, "> ") ? line.substr(2) : line);
        if (!open) {
            current.kind = BlockKind::Paragraph;
            open = true;
        }
        if (!pending.empty() && !joinsWithoutSpace(pending, content)) pending += ' ';
        pending += content;
    }
    if (inCode) blocks.push_back({BlockKind::CodeBlock, {}, 0, {{Style::Plain, code}}});
    close();
    return blocks;
}

std::vector<std::string_view> breakPieces(std::string_view text) {
    std::vector<std::string_view> pieces;
    std::size_t i = 0;
    while (i < text.size()) {
        const std::size_t begin = i;
        std::size_t length = 0;
        char32_t c = decodeUtf8(text, i, length);
        i += length;
        if (breaksAnywhere(c)) {
            // One character, with the closing punctuation that must not start a line.
            while (i < text.size()) {
                char32_t next = decodeUtf8(text, i, length);
                if (!isClosingPunctuation(next)) break;
                i += length;
            }
        } else {
            // A word: up to a space or a character a line may break before.
            while (i < text.size() && text[i] != ' ') {
                char32_t next = decodeUtf8(text, i, length);
                if (breaksAnywhere(next)) break;
                i += length;
            }
        }
        while (i < text.size() && text[i] == ' ') ++i;
        pieces.push_back(text.substr(begin, i - begin));
    }
    return pieces;
}

}  // namespace fx::markdown
