#pragma once
// Text on a Canvas with stb_easy_font: a public-domain vector font made of little rectangles, which
// we scale and rasterise ourselves. At scale 1 a capital letter is 7 pixels tall; scale 2 is the
// smallest size that reads comfortably in a 960-pixel-wide picture.
// Only printable ASCII is drawn; anything else shows as '?'.
#include <string_view>

#include "image/canvas.hpp"

namespace fx {

enum class TextDirection {
    Horizontal,  // left to right
    Upwards,     // rotated a quarter turn anticlockwise, read bottom to top (a y-axis label)
};

struct TextSize {
    double width = 0.0;   // along the reading direction
    double height = 0.0;  // across it: cap height plus room for descenders (g, p, y)
};

TextSize measureText(std::string_view text, double scale);

// (x, y) is the top-left corner of the text box as it reads: for Upwards text that corner ends up
// at the bottom-left of the drawn box, since the box is rotated about it. Single line only.
void drawText(Canvas& canvas, double x, double y, std::string_view text, double scale, Rgba colour,
              TextDirection direction = TextDirection::Horizontal);

}  // namespace fx
