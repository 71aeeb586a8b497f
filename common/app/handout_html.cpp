#include "app/handout_html.hpp"

#include <algorithm>

#include "base/markdown_text.hpp"

namespace fx::handout {
namespace {

using markdown::Block;
using markdown::BlockKind;
using markdown::Span;
using markdown::Style;

std::string spansHtml(const std::vector<Span>& spans, const PictureSource& pictures) {
    std::string out;
    for (const Span& s : spans) {
        switch (s.style) {
            case Style::Plain:
                out += escapeHtml(s.text);
                break;
            case Style::Strong:
                out += "<strong>" + escapeHtml(s.text) + "</strong>";
                break;
            case Style::Emphasis:
                out += "<em>" + escapeHtml(s.text) + "</em>";
                break;
            case Style::Code:
                out += "<code>" + escapeHtml(s.text) + "</code>";
                break;
            case Style::Picture:
                out +=
                    "<img src=\"" + escapeHtml(pictures(s.target)) + "\" alt=\"" + escapeHtml(s.text) + "\">";
                break;
        }
    }
    return out;
}

bool onlyAPicture(const Block& b) {
    return b.kind == BlockKind::Paragraph && b.cells.empty() && b.spans.size() == 1 &&
           b.spans.front().style == Style::Picture;
}

// Lists nest by their items' indent; an item stays open until the next item at its depth or above,
// so a deeper list goes inside it.
class ListWriter {
public:
    explicit ListWriter(std::string& out) : out_(out) {}
    void item(const Block& b, const std::string& content) {
        const std::size_t depth = std::min<std::size_t>(std::size_t(std::max(b.indent, 0)), open_.size());
        const bool ordered = b.marker != "-" && b.marker != "*";
        while (open_.size() > depth + 1) closeOne();
        if (open_.size() == depth + 1) {
            if (open_.back() != ordered) {
                closeOne();
            } else {
                out_ += "</li>\n";
            }
        }
        if (open_.size() == depth) {
            if (ordered) {
                const std::string number = b.marker.substr(0, b.marker.size() - 1);
                out_ += number == "1" ? "<ol>\n" : "<ol start=\"" + number + "\">\n";
            } else {
                out_ += "<ul>\n";
            }
            open_.push_back(ordered);
        }
        out_ += "<li>" + content;
    }
    void closeAll() {
        while (!open_.empty()) closeOne();
    }

private:
    void closeOne() {
        out_ += open_.back() ? "</li>\n</ol>\n" : "</li>\n</ul>\n";
        open_.pop_back();
    }
    std::string& out_;
    std::vector<bool> open_;  // per depth: ordered
};

void writeTable(std::string& out, const std::vector<const Block*>& rows, const PictureSource& pictures) {
    std::size_t columns = 0;
    for (const Block* r : rows) columns = std::max(columns, r->cells.size());
    out += "<table class=\"text-table\">\n";
    std::size_t first = 0;
    if (rows.front()->tableHeader) {
        out += "<thead><tr>";
        for (std::size_t c = 0; c < columns; ++c) {
            const auto& cells = rows.front()->cells;
            out += "<th>" + (c < cells.size() ? spansHtml(cells[c], pictures) : std::string()) + "</th>";
        }
        out += "</tr></thead>\n";
        first = 1;
    }
    out += "<tbody>\n";
    for (std::size_t r = first; r < rows.size(); ++r) {
        out += "<tr>";
        for (std::size_t c = 0; c < columns; ++c) {
            const auto& cells = rows[r]->cells;
            out += "<td>" + (c < cells.size() ? spansHtml(cells[c], pictures) : std::string()) + "</td>";
        }
        out += "</tr>\n";
    }
    out += "</tbody>\n</table>\n";
}

}  // namespace

std::string escapeHtml(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (char c : text) {
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            default:
                out += c;
        }
    }
    return out;
}

std::string markdownToHtml(std::string_view text, const PictureSource& pictures, int headingLevel) {
    const std::vector<Block> blocks = markdown::parseBlocks(text);
    std::string out;
    ListWriter lists(out);
    const std::string h = std::to_string(std::clamp(headingLevel, 1, 6));
    for (std::size_t i = 0; i < blocks.size(); ++i) {
        const Block& b = blocks[i];
        if (b.kind == BlockKind::ListItem) {
            lists.item(b, spansHtml(b.spans, pictures));
            continue;
        }
        lists.closeAll();
        if (!b.cells.empty()) {
            std::vector<const Block*> rows{&b};
            while (i + 1 < blocks.size() && !blocks[i + 1].cells.empty() && !blocks[i + 1].tableHeader)
                rows.push_back(&blocks[++i]);
            writeTable(out, rows, pictures);
            continue;
        }
        switch (b.kind) {
            case BlockKind::Heading:
                out += "<h" + h + ">" + spansHtml(b.spans, pictures) + "</h" + h + ">\n";
                break;
            case BlockKind::CodeBlock:
                out += "<pre><code>" + escapeHtml(b.spans.empty() ? std::string() : b.spans.front().text) +
                       "</code></pre>\n";
                break;
            case BlockKind::Paragraph:
                if (onlyAPicture(b)) {
                    const Span& p = b.spans.front();
                    out += "<figure class=\"text-figure\">" + spansHtml(b.spans, pictures);
                    if (!p.text.empty()) out += "<figcaption>" + escapeHtml(p.text) + "</figcaption>";
                    out += "</figure>\n";
                } else {
                    out += "<p>" + spansHtml(b.spans, pictures) + "</p>\n";
                }
                break;
            case BlockKind::ListItem:
                break;
        }
    }
    lists.closeAll();
    return out;
}

std::vector<std::string> pictureTargets(std::string_view text) {
    std::vector<std::string> targets;
    auto add = [&](const std::vector<Span>& spans) {
        for (const Span& s : spans) {
            if (s.style == Style::Picture &&
                std::find(targets.begin(), targets.end(), s.target) == targets.end())
                targets.push_back(s.target);
        }
    };
    for (const Block& b : markdown::parseBlocks(text)) {
        if (b.kind == BlockKind::CodeBlock) continue;
        if (b.cells.empty()) add(b.spans);
        for (const auto& cell : b.cells) add(cell);
    }
    return targets;
}

std::vector<std::string> codeSpans(std::string_view text) {
    std::vector<std::string> names;
    for (const Block& b : markdown::parseBlocks(text)) {
        if (b.kind == BlockKind::CodeBlock) continue;
        std::vector<Span> spans = b.spans;
        for (const auto& cell : b.cells) spans.insert(spans.end(), cell.begin(), cell.end());
        for (const Span& s : spans) {
            if (s.style == Style::Code && std::find(names.begin(), names.end(), s.text) == names.end())
                names.push_back(s.text);
        }
    }
    return names;
}

}  // namespace fx::handout
