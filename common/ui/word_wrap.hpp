#pragma once
// Short labels (pass names, texture names, table headers) wrapped to a narrow column at word
// boundaries: after a space, and after the ".", "_", "/" and "(" that join the words of a name
// ("particles.pool view" breaks as "particles." / "pool view"), never in the middle of a word. A word
// wider than the column alone is cut with "..." (the caller shows the whole text on hover).
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

// Draws `text` wrapped at words to the space left on the current line (ImGui), the whole text in a
// tooltip when a word had to be cut.
void drawWrappedName(const std::string& text);

}  // namespace fx
