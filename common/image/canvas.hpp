#pragma once
// A small RGBA drawing surface for pictures made on the CPU (the benchmark plot). Coordinates are
// in pixels with y growing DOWNWARDS, as one lays out a page; toImage() turns the result into the
// bottom-up ByteImage every other part of fxlab uses.
//
// Shapes are filled where a pixel's centre (x + 0.5, y + 0.5) lies inside them (rectangles include
// their top and left edges but not their bottom and right ones, so sizes come out exact). There is no
// anti-aliasing, but lines and discs are computed from distances, so thick lines have clean,
// even edges at any angle. Anything outside the canvas is clipped.
#include <cstdint>
#include <vector>

#include "image/image.hpp"

namespace fx {

struct Rgba {
    std::uint8_t r = 0, g = 0, b = 0, a = 255;
    friend bool operator==(const Rgba&, const Rgba&) = default;
};

class Canvas {
public:
    Canvas(int width, int height, Rgba background);

    int width() const { return width_; }
    int height() const { return height_; }

    Rgba pixel(int x, int y) const;            // (0, 0, 0, 0) outside the canvas
    void setPixel(int x, int y, Rgba colour);  // ignored outside the canvas

    // Axis-aligned rectangle from (x0, y0) to (x1, y1), corners in either order.
    void fillRect(double x0, double y0, double x1, double y1, Rgba colour);
    void strokeRect(double x0, double y0, double x1, double y1, double thickness, Rgba colour);
    void fillDisc(double cx, double cy, double radius, Rgba colour);
    void strokeCircle(double cx, double cy, double radius, double thickness, Rgba colour);
    // A square standing on its corner; `radius` is centre to corner.
    void fillDiamond(double cx, double cy, double radius, Rgba colour);
    void strokeDiamond(double cx, double cy, double radius, double thickness, Rgba colour);
    // A segment with round ends, `thickness` pixels wide.
    void drawLine(double x0, double y0, double x1, double y1, double thickness, Rgba colour);

    ByteImage toImage() const;

private:
    // Calls paint(x, y) for every pixel whose centre is inside [x0, x1] x [y0, y1], clipped.
    template <class Paint>
    void forPixelsIn(double x0, double y0, double x1, double y1, Paint paint);

    int width_ = 0, height_ = 0;
    std::vector<Rgba> pixels_;  // top row first
};

}  // namespace fx
