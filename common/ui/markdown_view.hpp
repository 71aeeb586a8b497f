#pragma once
// Draws a step's markdown text in the overlay (the subset base/markdown_text.hpp parses): paragraphs
// wrapped to the window, lists with bullets or numbers, `code` on a dark ground, **bold** in the
// heading colour, *emphasis* tinted, ``` blocks unwrapped; pictures are left out. Japanese
// wraps between characters, since it has no spaces.
#include <string_view>

namespace fx {

void drawMarkdown(std::string_view text);

}  // namespace fx
