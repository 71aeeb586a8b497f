#include "ui/word_wrap.hpp"

#include <imgui.h>

namespace fx {
namespace {

bool breaksAfter(char c) {
    return c == ' ' || c == '.' || c == '_' || c == '/' || c == '(';
}

// The words with what follows them: "a.b c" -> "a.", "b ", "c".
std::vector<std::string_view> words(std::string_view text) {
    std::vector<std::string_view> out;
    std::size_t start = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const bool last = i + 1 == text.size();
        // A run of spaces stays with the word before it.
        if (last || (breaksAfter(text[i]) && text[i + 1] != ' ')) {
            out.push_back(text.substr(start, i + 1 - start));
            start = i + 1;
        }
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

void drawWrappedName(const std::string& text) {
    const float width = ImGui::GetContentRegionAvail().x;
    const WrappedText wrapped = wrapAtWords(
        text, width, [](std::string_view s) { return ImGui::CalcTextSize(s.data(), s.data() + s.size()).x; });
    ImGui::BeginGroup();
    for (const std::string& line : wrapped.lines) ImGui::TextUnformatted(line.c_str());
    ImGui::EndGroup();
    if (wrapped.elided && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text.c_str());
}

}  // namespace fx
