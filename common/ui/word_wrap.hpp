#pragma once
// Short labels (pass names, texture names, table headers) wrapped to a narrow column where Unicode's
// rules let a line break (base/line_break.hpp: words, Japanese between characters, never inside a
// number), and after the ".", "_", "/" and "(" that join the words of a name ("particles.pool view"
// breaks as "particles." / "pool view"), never in the middle of a word. A word wider than the column
// alone is cut with "..." (the caller shows the whole text on hover).
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace fx {

struct WrappedText {
    std::vector<std::string> lines;
    bool elided = false;  // some word did not fit and was cut
};

// `measure` gives a piece of text's width in the same unit as `width`.
WrappedText wrapAtWords(std::string_view text, float width,
                        const std::function<float(std::string_view)>& measure);

// `text` on one line at most `width` wide: whole where it fits, else its start with "..." (elided).
WrappedText oneLine(std::string_view text, float width,
                    const std::function<float(std::string_view)>& measure);

// Draws `text` on one line in the space left on the current line (ImGui), cut with "..." where it is
// wider, the whole text in a tooltip then: a table row stays one line tall.
void drawOneLine(const std::string& text);

// Draws `text` wrapped at words to the space left on the current line (ImGui), the whole text in a
// tooltip when a word had to be cut.
void drawWrappedName(const std::string& text);

// Draws a line of prose (a step's title, a fact) wrapped to the window's width by Unicode's rules
// (base/line_break.hpp: numbers never split, no lone character on the last line).
void drawWrappedText(std::string_view text);

}  // namespace fx
