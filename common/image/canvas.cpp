#include "image/canvas.hpp"

#include <algorithm>
#include <cmath>

namespace fx {

Canvas::Canvas(int width, int height, Rgba background)
    : width_(std::max(width, 0)),
      height_(std::max(height, 0)),
      pixels_(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_), background) {}

Rgba Canvas::pixel(int x, int y) const {
    if (x < 0 || y < 0 || x >= width_ || y >= height_) return Rgba{0, 0, 0, 0};
    return pixels_[static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
                   static_cast<std::size_t>(x)];
}

void Canvas::setPixel(int x, int y, Rgba colour) {
    if (x < 0 || y < 0 || x >= width_ || y >= height_) return;
    pixels_[static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x)] =
        colour;
}

template <class Paint>
void Canvas::forPixelsIn(double x0, double y0, double x1, double y1, Paint paint) {
    if (!(x0 <= x1) || !(y0 <= y1)) return;  // also rejects NaN corners
    // Pixel x has its centre at x + 0.5 and is inside when x0 <= x + 0.5 < x1: half-open, so a
    // rectangle 2 pixels wide covers exactly 2 pixels wherever it lies. Bounds are clamped to the
    // canvas before they become ints, so far-away shapes cannot overflow the conversion.
    const auto first = [](double low, int size) {
        return static_cast<int>(std::ceil(std::clamp(low - 0.5, -1.0, static_cast<double>(size))));
    };
    const auto last = [](double high, int size) {
        return static_cast<int>(std::ceil(std::clamp(high - 0.5, -1.0, static_cast<double>(size)))) - 1;
    };
    const int firstX = std::max(0, first(x0, width_)), lastX = std::min(width_ - 1, last(x1, width_));
    const int firstY = std::max(0, first(y0, height_)), lastY = std::min(height_ - 1, last(y1, height_));
    for (int y = firstY; y <= lastY; ++y)
        for (int x = firstX; x <= lastX; ++x) paint(x, y);
}

void Canvas::fillRect(double x0, double y0, double x1, double y1, Rgba colour) {
    forPixelsIn(std::min(x0, x1), std::min(y0, y1), std::max(x0, x1), std::max(y0, y1),
                [&](int x, int y) { setPixel(x, y, colour); });
}

void Canvas::strokeRect(double x0, double y0, double x1, double y1, double thickness, Rgba colour) {
    const double left = std::min(x0, x1), right = std::max(x0, x1);
    const double top = std::min(y0, y1), bottom = std::max(y0, y1);
    const double half = thickness / 2.0;
    fillRect(left - half, top - half, right + half, top + half, colour);
    fillRect(left - half, bottom - half, right + half, bottom + half, colour);
    fillRect(left - half, top - half, left + half, bottom + half, colour);
    fillRect(right - half, top - half, right + half, bottom + half, colour);
}

void Canvas::fillDisc(double cx, double cy, double radius, Rgba colour) {
    forPixelsIn(cx - radius, cy - radius, cx + radius, cy + radius, [&](int x, int y) {
        const double dx = x + 0.5 - cx, dy = y + 0.5 - cy;
        if (dx * dx + dy * dy <= radius * radius) setPixel(x, y, colour);
    });
}

void Canvas::strokeCircle(double cx, double cy, double radius, double thickness, Rgba colour) {
    const double outer = radius + thickness / 2.0, inner = std::max(0.0, radius - thickness / 2.0);
    forPixelsIn(cx - outer, cy - outer, cx + outer, cy + outer, [&](int x, int y) {
        const double dx = x + 0.5 - cx, dy = y + 0.5 - cy;
        const double d2 = dx * dx + dy * dy;
        if (d2 <= outer * outer && d2 >= inner * inner) setPixel(x, y, colour);
    });
}

void Canvas::fillDiamond(double cx, double cy, double radius, Rgba colour) {
    forPixelsIn(cx - radius, cy - radius, cx + radius, cy + radius, [&](int x, int y) {
        if (std::abs(x + 0.5 - cx) + std::abs(y + 0.5 - cy) <= radius) setPixel(x, y, colour);
    });
}

void Canvas::strokeDiamond(double cx, double cy, double radius, double thickness, Rgba colour) {
    // |dx| + |dy| = r is a line at 45 degrees, so the distance to it is (|dx| + |dy| - r) / sqrt(2).
    const double halfWidth = thickness / 2.0 * std::sqrt(2.0);
    const double outer = radius + halfWidth;
    forPixelsIn(cx - outer, cy - outer, cx + outer, cy + outer, [&](int x, int y) {
        const double taxicab = std::abs(x + 0.5 - cx) + std::abs(y + 0.5 - cy);
        if (std::abs(taxicab - radius) <= halfWidth) setPixel(x, y, colour);
    });
}

void Canvas::drawLine(double x0, double y0, double x1, double y1, double thickness, Rgba colour) {
    const double half = thickness / 2.0;
    const double dx = x1 - x0, dy = y1 - y0;
    const double lengthSquared = dx * dx + dy * dy;
    forPixelsIn(std::min(x0, x1) - half, std::min(y0, y1) - half, std::max(x0, x1) + half,
                std::max(y0, y1) + half, [&](int x, int y) {
                    const double px = x + 0.5 - x0, py = y + 0.5 - y0;
                    // The closest point of the segment; a zero-length segment is its first end.
                    const double t =
                        lengthSquared > 0.0 ? std::clamp((px * dx + py * dy) / lengthSquared, 0.0, 1.0) : 0.0;
                    const double ex = px - t * dx, ey = py - t * dy;
                    if (ex * ex + ey * ey <= half * half) setPixel(x, y, colour);
                });
}

ByteImage Canvas::toImage() const {
    ByteImage image = makeByteImage(width_, height_, 4);
    for (int y = 0; y < height_; ++y) {
        const int row = height_ - 1 - y;  // the canvas's top row is the image's last
        for (int x = 0; x < width_; ++x) {
            const Rgba p = pixel(x, y);
            std::uint8_t* out = &image.texel(x, row, 0);
            out[0] = p.r;
            out[1] = p.g;
            out[2] = p.b;
            out[3] = p.a;
        }
    }
    return image;
}

}  // namespace fx
