#include "image/canvas_text.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wall"
#pragma GCC diagnostic ignored "-Wextra"
#pragma GCC diagnostic ignored "-Wpedantic"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wold-style-cast"
#pragma GCC diagnostic ignored "-Wcast-align"
#include <stb/stb_easy_font.h>
#pragma GCC diagnostic pop

namespace fx {
namespace {

// The font's glyphs are 7 units above the baseline row and descenders reach 2 units below.
constexpr double kGlyphHeight = 9.0;

// stb_easy_font indexes a table by (character - 32) and takes a mutable C string, so it gets a
// sanitised, NUL-terminated copy of one line.
std::string printableCopy(std::string_view text) {
    std::string copy(text);
    for (char& c : copy)
        if (c < 32 || c > 126) c = '?';
    return copy;
}

// stb_easy_font writes 4 vertices of 16 bytes (x, y, z as floats, then 4 colour bytes) per quad.
struct FontVertex {
    float x, y, z;
    unsigned char colour[4];
};
static_assert(sizeof(FontVertex) == 16);

}  // namespace

TextSize measureText(std::string_view text, double scale) {
    if (text.empty()) return {};
    std::string copy = printableCopy(text);
    // The font's width counts the gap after the last letter; remove it so boxes hug the ink.
    const double width = std::max(0, stb_easy_font_width(copy.data()) - 1);
    return TextSize{width * scale, kGlyphHeight * scale};
}

void drawText(Canvas& canvas, double x, double y, std::string_view text, double scale, Rgba colour,
              TextDirection direction) {
    if (text.empty()) return;
    std::string copy = printableCopy(text);
    // Whole-pixel origins keep every stroke equally wide: the font's strokes are whole units.
    x = std::round(x);
    y = std::round(y);
    // The font header suggests about 270 bytes per character; leave generous room.
    std::vector<FontVertex> vertices(copy.size() * 64 + 64);
    const int quads = stb_easy_font_print(0.0f, 0.0f, copy.data(), nullptr, vertices.data(),
                                          static_cast<int>(vertices.size() * sizeof(FontVertex)));
    for (int q = 0; q < quads; ++q) {
        const FontVertex* corner = &vertices[static_cast<std::size_t>(q) * 4];
        // Every quad is an axis-aligned rectangle; its opposite corners are vertices 0 and 2.
        const double u0 = std::min(corner[0].x, corner[2].x) * scale,
                     u1 = std::max(corner[0].x, corner[2].x) * scale;
        const double v0 = std::min(corner[0].y, corner[2].y) * scale,
                     v1 = std::max(corner[0].y, corner[2].y) * scale;
        if (direction == TextDirection::Horizontal) {
            canvas.fillRect(x + u0, y + v0, x + u1, y + v1, colour);
        } else {
            // A quarter turn anticlockwise: reading direction u goes up the page, v goes right.
            canvas.fillRect(x + v0, y - u1, x + v1, y - u0, colour);
        }
    }
}

}  // namespace fx
