#include "ui/markdown_view.hpp"

#include <algorithm>
#include <cfloat>
#include <string>

#include <imgui.h>

#include "base/line_break.hpp"
#include "base/markdown_text.hpp"
#include "ui/ui_style.hpp"

namespace fx {
namespace {

using markdown::Block;
using markdown::BlockKind;
using markdown::Span;
using markdown::Style;

const ImVec4 kCode{0.62f, 0.86f, 0.70f, 1.0f};
const ImVec4 kCodeGround{1.0f, 1.0f, 1.0f, 0.08f};
const ImVec4 kEmphasis{0.72f, 0.82f, 1.0f, 1.0f};

float widthOf(std::string_view s) {
    return ImGui::GetFont()
        ->CalcTextSizeA(ImGui::GetFontSize(), FLT_MAX, 0.0f, s.data(), s.data() + s.size())
        .x;
}

std::string_view withoutTrailingSpaces(std::string_view s) {
    while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
    return s;
}

// Lays the spans out from `origin` in lines at most `width` wide; returns the height used.
float drawFlow(const std::vector<Span>& spans, ImVec2 origin, float width) {
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const float lineHeight = ImGui::GetTextLineHeight() + 2.0f;
    float x = 0.0f, y = 0.0f;
    for (const Span& span : spans) {
        const std::string_view text = span.text;
        const ImVec4 colour = span.style == Style::Strong     ? ui_style::kHeading
                              : span.style == Style::Code     ? kCode
                              : span.style == Style::Emphasis ? kEmphasis
                                                              : ImGui::GetStyle().Colors[ImGuiCol_Text];
        for (std::string_view piece : lineBreakPieces(text)) {
            if (x == 0.0f) {
                while (!piece.empty() && piece.front() == ' ') piece.remove_prefix(1);
                if (piece.empty()) continue;
            }
            const float visible = widthOf(withoutTrailingSpaces(piece));
            if (x > 0.0f && x + visible > width) {
                x = 0.0f;
                y += lineHeight;
                while (!piece.empty() && piece.front() == ' ') piece.remove_prefix(1);
            }
            const ImVec2 at(origin.x + x, origin.y + y);
            if (span.style == Style::Code) {
                draw->AddRectFilled(ImVec2(at.x - 1, at.y - 1),
                                    ImVec2(at.x + visible + 1, at.y + lineHeight - 2),
                                    ui_style::packed(kCodeGround), 2.0f);
            }
            draw->AddText(at, ui_style::packed(colour), piece.data(), piece.data() + piece.size());
            if (span.style == Style::Strong) {
                // The built-in font has no bold: drawing it again a pixel to the right thickens it.
                draw->AddText(ImVec2(at.x + 1, at.y), ui_style::packed(colour), piece.data(),
                              piece.data() + piece.size());
            }
            x += widthOf(piece);
        }
    }
    return x > 0.0f || y > 0.0f ? y + lineHeight : 0.0f;
}

// A table's rows (blocks with cells; the first may be its header) in columns: each column as wide as
// its widest cell where the text's width allows, otherwise shared in proportion, its cells wrapped.
// Returns the height used.
float drawTable(std::vector<Block*> rows, ImVec2 origin, float width) {
    const float em = ImGui::GetFontSize();
    const float pad = 0.4f * em;
    std::size_t columns = 0;
    for (Block* r : rows) {
        for (auto& cell : r->cells)
            std::erase_if(cell, [](const Span& s) { return s.style == Style::Picture; });
        columns = std::max(columns, r->cells.size());
    }
    if (columns == 0) return 0.0f;
    // Each column between its widest word (a line cannot break inside one) and its widest cell on one
    // line; what the text's width leaves over the least goes to the columns that want more, in
    // proportion to what they want, so a table never runs past the text's right edge if it can help it.
    std::vector<float> natural(columns, 0.0f), least(columns, 0.0f);
    for (const Block* r : rows) {
        for (std::size_t c = 0; c < r->cells.size(); ++c) {
            float w = 0.0f;
            for (const Span& s : r->cells[c]) {
                w += widthOf(s.text);
                for (std::string_view piece : lineBreakPieces(s.text))
                    least[c] = std::max(least[c], widthOf(withoutTrailingSpaces(piece)) + 2 * pad + 1.0f);
            }
            natural[c] = std::max(natural[c], w + 2 * pad + 1.0f);
        }
    }
    float leastTotal = 0.0f, wanted = 0.0f;
    for (std::size_t c = 0; c < columns; ++c) {
        natural[c] = std::max(natural[c], least[c]);
        leastTotal += least[c];
        wanted += natural[c] - least[c];
    }
    std::vector<float> column = least;
    const float spare = std::max(width - leastTotal, 0.0f);
    for (std::size_t c = 0; c < columns; ++c)
        column[c] += wanted > 0.0f ? std::min(1.0f, spare / wanted) * (natural[c] - least[c]) : 0.0f;
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImU32 rule = ui_style::packed(ImVec4(1.0f, 1.0f, 1.0f, 0.18f));
    float y = 0.0f;
    for (const Block* r : rows) {
        float x = 0.0f, height = 0.0f;
        for (std::size_t c = 0; c < columns; ++c) {
            if (c < r->cells.size()) {
                std::vector<Span> cell = r->cells[c];
                if (r->tableHeader)
                    for (Span& s : cell) s.style = Style::Strong;
                height = std::max(height, drawFlow(cell, ImVec2(origin.x + x + pad, origin.y + y + 2.0f),
                                                   column[c] - 2 * pad));
            }
            x += column[c];
        }
        height = std::max(height, ImGui::GetTextLineHeight()) + 4.0f;
        y += height;
        draw->AddLine(ImVec2(origin.x, origin.y + y), ImVec2(origin.x + x, origin.y + y), rule,
                      r->tableHeader ? 2.0f : 1.0f);
    }
    float x = 0.0f;
    for (std::size_t c = 0; c + 1 < columns; ++c) {
        x += column[c];
        draw->AddLine(ImVec2(origin.x + x, origin.y), ImVec2(origin.x + x, origin.y + y), rule);
    }
    return y;
}

}  // namespace

void drawMarkdown(std::string_view text) {
    const float em = ImGui::GetFontSize();
    const float width = std::max(ImGui::GetContentRegionAvail().x, 4 * em);
    const ImVec2 start = ImGui::GetCursorScreenPos();
    float y = 0.0f;
    bool first = true;
    std::vector<Block> blocks = markdown::parseBlocks(text);
    for (std::size_t i = 0; i < blocks.size(); ++i) {
        Block& block = blocks[i];
        if (!block.cells.empty()) {
            // A table: this row and those after it up to the next table's header.
            std::vector<Block*> rows{&block};
            while (i + 1 < blocks.size() && !blocks[i + 1].cells.empty() && !blocks[i + 1].tableHeader)
                rows.push_back(&blocks[++i]);
            const bool onlyPictures = std::all_of(rows.begin(), rows.end(), [](const Block* r) {
                return std::all_of(r->cells.begin(), r->cells.end(), [](const std::vector<Span>& cell) {
                    return std::all_of(cell.begin(), cell.end(),
                                       [](const Span& s) { return s.style == Style::Picture; });
                });
            });
            if (onlyPictures) continue;  // a table of pictures: the picture is on the screen already
            if (!first) y += 0.5f * em;
            first = false;
            y += drawTable(rows, ImVec2(start.x, start.y + y), width);
            continue;
        }
        // Pictures are left out: the picture is on the screen already, and the step's text reads
        // without them.
        std::erase_if(block.spans, [](const Span& s) { return s.style == Style::Picture; });
        const bool nothingLeft = std::all_of(block.spans.begin(), block.spans.end(), [](const Span& s) {
            return s.style == Style::Plain && s.text.find_first_not_of(" |") == std::string::npos;
        });
        if (nothingLeft && block.kind != BlockKind::ListItem) continue;  // e.g. a table row of pictures
        if (!first) y += block.kind == BlockKind::ListItem ? 2.0f : 0.5f * em;
        first = false;
        const ImVec2 origin(start.x, start.y + y);
        switch (block.kind) {
            case BlockKind::Paragraph:
                y += drawFlow(block.spans, origin, width);
                break;
            case BlockKind::Heading: {
                std::vector<Span> strong;
                for (const Span& s : block.spans) strong.push_back({Style::Strong, s.text});
                y += drawFlow(strong, origin, width);
                break;
            }
            case BlockKind::ListItem: {
                const float indent = 1.2f * em * float(block.indent);
                const float markerWidth = block.marker == "-" || block.marker == "*"
                                              ? 1.2f * em
                                              : widthOf(block.marker) + 0.5f * em;
                ImDrawList* draw = ImGui::GetWindowDrawList();
                const ImU32 textColour = ui_style::packed(ImGui::GetStyle().Colors[ImGuiCol_Text]);
                if (markerWidth == 1.2f * em) {
                    draw->AddCircleFilled(ImVec2(origin.x + indent + 0.45f * em, origin.y + 0.55f * em),
                                          0.16f * em, textColour);
                } else {
                    draw->AddText(ImVec2(origin.x + indent, origin.y), textColour, block.marker.c_str());
                }
                const float left = indent + markerWidth;
                y += std::max(drawFlow(block.spans, ImVec2(origin.x + left, origin.y), width - left),
                              ImGui::GetTextLineHeight());
                break;
            }
            case BlockKind::CodeBlock: {
                const std::string& code = block.spans.empty() ? std::string() : block.spans.front().text;
                const ImVec2 size = ImGui::CalcTextSize(code.c_str());
                ImDrawList* draw = ImGui::GetWindowDrawList();
                draw->AddRectFilled(origin,
                                    ImVec2(origin.x + std::min(size.x, width) + 8, origin.y + size.y + 6),
                                    ui_style::packed(kCodeGround), 2.0f);
                draw->PushClipRect(origin, ImVec2(origin.x + width, origin.y + size.y + 6), true);
                draw->AddText(ImVec2(origin.x + 4, origin.y + 3), ui_style::packed(kCode), code.c_str());
                draw->PopClipRect();
                y += size.y + 6;
                break;
            }
        }
    }
    ImGui::Dummy(ImVec2(width, y));
}

}  // namespace fx
