#pragma once
// A width and height in texels or pixels: a window's framebuffer, the frame's output, a texture, a
// mip level. One struct for all of them, so sizes pass between layers without conversion.
#include <string>

namespace fx {

struct Size2D {
    int width = 0;
    int height = 0;
    bool empty() const { return width <= 0 || height <= 0; }
    bool operator==(const Size2D&) const = default;
};

std::string toString(Size2D size);  // "1279x719"

}  // namespace fx
