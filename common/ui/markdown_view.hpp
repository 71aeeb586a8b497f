#pragma once
// Draws a step's markdown text in the overlay (the blocks base/markdown_text.hpp reads): paragraphs
// wrapped to the window where Unicode's rules let a line break (base/line_break.hpp, Japanese rules
// included), lists with bullets or numbers, tables in columns, `code` on a dark ground, **bold** in
// the heading colour, *emphasis* tinted, ``` blocks unwrapped; pictures are left out.
#include <string_view>

namespace fx {

void drawMarkdown(std::string_view text);

}  // namespace fx
