#include "ui/word_wrap.hpp"

#include <algorithm>
#include <cctype>

#include <imgui.h>

#include "base/line_break.hpp"

namespace fx {
namespace {

bool breaksAfter(char c) {
    return c == '.' || c == '_' || c == '/' || c == '(';
}

// The places a line may break (Unicode's rules, base/line_break.hpp), and inside a name after the
// ".", "_", "/" and "(" that join its words: "particles.pool view" -> "particles.", "pool ", "view".
// A dot between digits is a number's ("0.25") and stays.
std::vector<std::string_view> words(std::string_view text) {
    std::vector<std::string_view> out;
    for (std::string_view piece : lineBreakPieces(text)) {
        std::size_t start = 0;
        for (std::size_t i = 0; i + 1 < piece.size(); ++i) {
            const bool digits = i > 0 && std::isdigit(static_cast<unsigned char>(piece[i - 1])) &&
                                std::isdigit(static_cast<unsigned char>(piece[i + 1]));
            // A space always ends a word of a name, even before "/" ("inherited / left").
            if ((breaksAfter(piece[i]) || piece[i] == ' ') && piece[i + 1] != ' ' && !digits) {
                out.push_back(piece.substr(start, i + 1 - start));
                start = i + 1;
            }
        }
        out.push_back(piece.substr(start));
    }
    return out;
}

// The longest start of `word` that fits in `width` with "..." after it (at least one character).
std::string elide(std::string_view word, float width, const std::function<float(std::string_view)>& measure) {
    std::size_t keep = word.size();
    while (keep > 1 && measure(std::string(word.substr(0, keep)) + "...") > width) {
        --keep;
        while (keep > 1 && (static_cast<unsigned char>(word[keep]) & 0xC0) == 0x80)
            --keep;  // whole UTF-8 characters
    }
    return std::string(word.substr(0, keep)) + "...";
}

std::string_view trimRight(std::string_view s) {
    while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
    return s;
}

}  // namespace

WrappedText wrapAtWords(std::string_view text, float width,
                        const std::function<float(std::string_view)>& measure) {
    WrappedText out;
    std::string line;
    for (std::string_view word : words(text)) {
        const std::string joined = line + std::string(word);
        if (line.empty() || measure(trimRight(joined)) <= width) {
            line = joined;
        } else {
            out.lines.emplace_back(trimRight(line));
            line = std::string(word);
        }
        if (measure(trimRight(line)) > width) {
            // One word alone is too wide for the column: cut it, never break it across lines.
            out.lines.push_back(elide(trimRight(line), width, measure));
            out.elided = true;
            line.clear();
        }
    }
    if (!trimRight(line).empty()) out.lines.emplace_back(trimRight(line));
    return out;
}

WrappedText oneLine(std::string_view text, float width,
                    const std::function<float(std::string_view)>& measure) {
    WrappedText out;
    if (text.empty()) return out;
    if (measure(text) <= width) {
        out.lines.emplace_back(text);
    } else {
        out.lines.push_back(elide(text, width, measure));
        out.elided = true;
    }
    return out;
}

void drawOneLine(const std::string& text) {
    const WrappedText line = oneLine(text, ImGui::GetContentRegionAvail().x, [](std::string_view s) {
        return ImGui::CalcTextSize(s.data(), s.data() + s.size()).x;
    });
    if (line.lines.empty()) return;
    ImGui::TextUnformatted(line.lines.front().c_str());
    if (line.elided && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text.c_str());
}

void drawWrappedName(const std::string& text) {
    const float width = ImGui::GetContentRegionAvail().x;
    const WrappedText wrapped = wrapAtWords(
        text, width, [](std::string_view s) { return ImGui::CalcTextSize(s.data(), s.data() + s.size()).x; });
    ImGui::BeginGroup();
    for (const std::string& line : wrapped.lines) ImGui::TextUnformatted(line.c_str());
    ImGui::EndGroup();
    if (wrapped.elided && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text.c_str());
}

void drawWrappedText(std::string_view text) {
    const float width = std::max(ImGui::GetContentRegionAvail().x, ImGui::GetFontSize());
    ImGui::BeginGroup();
    for (const std::string& line : wrapLines(text, width, [](std::string_view s) {
             return ImGui::CalcTextSize(s.data(), s.data() + s.size()).x;
         }))
        ImGui::TextUnformatted(line.c_str());
    ImGui::EndGroup();
}

}  // namespace fx
