#include "image/plot.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "image/canvas_text.hpp"
#include "image/plot_style.hpp"

namespace fx {
namespace {

using namespace plot_colours;
using namespace plot_style;

constexpr double kPointRadius = 6.0;
constexpr double kCurrentRadius = 7.0, kCurrentRingRadius = 12.0;
constexpr double kReferenceRadius = 10.0;
constexpr double kFrontThickness = 3.0;

using PixelPoint = std::array<double, 2>;

struct Box {
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;

    double overlap(const Box& o) const {
        const double w = std::min(x1, o.x1) - std::max(x0, o.x0), h = std::min(y1, o.y1) - std::max(y0, o.y0);
        return w > 0 && h > 0 ? w * h : 0.0;
    }
    bool contains(const PixelPoint& p) const { return p[0] >= x0 && p[0] <= x1 && p[1] >= y0 && p[1] <= y1; }
    double area() const { return (x1 - x0) * (y1 - y0); }
    Box grownBy(double d) const { return {x0 - d, y0 - d, x1 + d, y1 + d}; }
};

// How far from a marker's centre its drawing reaches (including the white halo).
double markerRadius(const PlotPoint& point) {
    if (point.isCurrent) return kCurrentRingRadius + 1.0;
    if (point.isReference) return kReferenceRadius + 1.5;
    return kPointRadius + 2.0;
}

void drawMarker(Canvas& canvas, const PlotPoint& point, double px, double py) {
    if (point.isReference) {
        canvas.fillDiamond(px, py, kReferenceRadius + 1.5, kBackground);
        canvas.strokeDiamond(px, py, kReferenceRadius, 2.5, kInk);
        canvas.fillDisc(px, py, 2.5, point.isCurrent ? kCurrent : kInk);
    } else {
        // A white halo keeps neighbouring discs apart and lifts the disc off the front's line.
        const double radius = point.isCurrent ? kCurrentRadius : kPointRadius;
        canvas.fillDisc(px, py, radius + 1.5, kBackground);
        canvas.fillDisc(px, py, radius, point.isCurrent ? kCurrent : kPoint);
    }
    if (point.isCurrent) canvas.strokeCircle(px, py, kCurrentRingRadius, 2.0, kCurrent);
}

// Positions along a polyline a few pixels apart, for keeping text off the lines drawn.
std::vector<PixelPoint> sampleLine(const std::vector<PixelPoint>& corners) {
    std::vector<PixelPoint> samples;
    for (std::size_t i = 0; i + 1 < corners.size(); ++i) {
        const double dx = corners[i + 1][0] - corners[i][0], dy = corners[i + 1][1] - corners[i][1];
        const int steps = std::clamp(static_cast<int>(std::hypot(dx, dy) / 4.0), 1, 2000);
        for (int s = 0; s <= steps; ++s)
            samples.push_back({corners[i][0] + dx * s / steps, corners[i][1] + dy * s / steps});
    }
    return samples;
}

// Paints one plot, back to front: grid and axes, the front's line, markers, legend, labels, notes.
// Text is placed last and avoids what is already drawn (see crowding()).
class ScatterPlotPainter {
public:
    ScatterPlotPainter(const ScatterPlot& plot, int width, int height)
        : plot_(plot),
          layout_(layoutScatterPlot(plot, width, height)),
          canvas_(width, height, kBackground),
          rowHeight_(lineHeight()),
          pixels_(plot.points.size()) {
        for (std::size_t i = 0; i < plot.points.size(); ++i) {
            if (!layout_.isDrawable(plot.points[i])) continue;
            drawable_.push_back(i);
            pixels_[i] = {layout_.pixelX(plot.points[i].x), layout_.pixelY(plot.points[i].y)};
        }
        front_ = paretoFront(plot.points);
    }

    ByteImage paint() {
        drawAxes();
        drawTitleAndAxisLabels();
        drawFrontAndMarkers();
        drawLegend();
        drawPointLabels();
        drawNotes();
        return canvas_.toImage();
    }

private:
    const PlotPoint& point(std::size_t i) const { return plot_.points[i]; }

    void drawAxes() {
        for (std::size_t i = 0; i < layout_.xAxis.ticks.size(); ++i) {
            const double px = std::round(layout_.pixelX(layout_.xAxis.ticks[i]));
            canvas_.fillRect(px, layout_.top, px + 1.0, layout_.bottom, kGrid);
            canvas_.fillRect(px, layout_.bottom, px + 1.0, layout_.bottom + kTickLength, kInk);
            const std::string& label = layout_.xAxis.tickLabels[i];
            drawText(canvas_, px - measureText(label, kTextScale).width / 2.0,
                     layout_.bottom + kTickLength + kTickLabelGap, label, kTextScale, kInk);
        }
        const double floorY = layout_.yFloor > 0.0 ? std::round(layout_.pixelY(layout_.yFloor)) : -1e9;
        for (std::size_t i = 0; i < layout_.yAxis.ticks.size(); ++i) {
            const double py = std::round(layout_.pixelY(layout_.yAxis.ticks[i]));
            if (std::abs(py - floorY) < rowHeight_) continue;  // the floor's "0" takes that place
            canvas_.fillRect(layout_.left, py, layout_.right, py + 1.0, kGrid);
            canvas_.fillRect(layout_.left - kTickLength, py, layout_.left, py + 1.0, kInk);
            drawYTickLabel(py, layout_.yAxis.tickLabels[i], kInk);
        }
        if (layout_.yFloor > 0.0) {
            // The floor stands for "zero or below", which a log axis cannot show: a dashed line marked 0.
            for (double x = layout_.left; x < layout_.right; x += 12.0)
                canvas_.fillRect(x, floorY, std::min(x + 6.0, layout_.right), floorY + 1.0, kNote);
            drawYTickLabel(floorY, "0", kNote);
        }
        canvas_.strokeRect(layout_.left, layout_.top, layout_.right + 1.0, layout_.bottom + 1.0, 2.0, kInk);
    }

    void drawYTickLabel(double py, const std::string& label, Rgba colour) {
        const TextSize size = measureText(label, kTextScale);
        drawText(canvas_, layout_.left - kTickLength - kTickLabelGap - size.width,
                 py - size.height / 2.0 + 1.0, label, kTextScale, colour);
    }

    void drawTitleAndAxisLabels() {
        if (!plot_.title.empty()) {
            const TextSize size = measureText(plot_.title, kTitleScale);
            drawText(canvas_, std::max(kMargin, (canvas_.width() - size.width) / 2.0), kMargin, plot_.title,
                     kTitleScale, kInk);
        }
        if (!plot_.xLabel.empty()) {
            const TextSize size = measureText(plot_.xLabel, kTextScale);
            drawText(canvas_, (layout_.left + layout_.right - size.width) / 2.0, layout_.xLabelTop,
                     plot_.xLabel, kTextScale, kInk);
        }
        if (!plot_.yLabel.empty()) {
            const TextSize size = measureText(plot_.yLabel, kTextScale);
            drawText(canvas_, kMargin, (layout_.top + layout_.bottom + size.width) / 2.0, plot_.yLabel,
                     kTextScale, kInk, TextDirection::Upwards);
        }
        if (drawable_.empty()) {
            const std::string text = "no data";
            const TextSize size = measureText(text, kTitleScale);
            drawText(canvas_, (layout_.left + layout_.right - size.width) / 2.0,
                     (layout_.top + layout_.bottom - size.height) / 2.0, text, kTitleScale, kNote);
        }
    }

    void drawFrontAndMarkers() {
        std::vector<PixelPoint> corners;
        for (std::size_t i : front_) corners.push_back(pixels_[i]);
        // The line goes under the markers, so every marker stays whole.
        for (std::size_t i = 0; i + 1 < corners.size(); ++i)
            canvas_.drawLine(corners[i][0], corners[i][1], corners[i + 1][0], corners[i + 1][1],
                             kFrontThickness, kParetoFront);
        lineSamples_ = sampleLine(corners);
        if (layout_.yFloor > 0.0) {
            const double py = layout_.pixelY(layout_.yFloor);
            for (const PixelPoint& sample : sampleLine({{layout_.left, py}, {layout_.right, py}}))
                lineSamples_.push_back(sample);
        }

        // Ordinary points first, then the current one, then the reference, so the special ones end on top.
        drawOrder_ = drawable_;
        const auto rank = [&](std::size_t i) {
            return point(i).isReference ? 2 : point(i).isCurrent ? 1 : 0;
        };
        std::stable_sort(drawOrder_.begin(), drawOrder_.end(),
                         [&](std::size_t a, std::size_t b) { return rank(a) < rank(b); });
        for (std::size_t i : drawOrder_) {
            drawMarker(canvas_, point(i), pixels_[i][0], pixels_[i][1]);
            const double r = markerRadius(point(i));
            obstacles_.push_back(
                {pixels_[i][0] - r, pixels_[i][1] - r, pixels_[i][0] + r, pixels_[i][1] + r});
        }
    }

    // How much a text or legend box would hide: overlap with what is drawn, lines it crosses, and
    // (weighted most) whatever part of it falls outside the plot area.
    double crowding(const Box& box) const {
        double cost = 0.0;
        for (const Box& obstacle : obstacles_) cost += box.overlap(obstacle);
        for (const PixelPoint& sample : lineSamples_)
            if (box.contains(sample)) cost += 16.0;
        const Box area{layout_.left, layout_.top, layout_.right, layout_.bottom};
        cost += (box.area() - box.overlap(area)) * 4.0;
        return cost;
    }

    template <std::size_t N>
    Box leastCrowded(const std::array<Box, N>& candidates, double clearance) const {
        return *std::min_element(candidates.begin(), candidates.end(), [&](const Box& a, const Box& b) {
            return crowding(a.grownBy(clearance)) < crowding(b.grownBy(clearance));
        });
    }

    void drawLegend() {
        enum class Swatch { Measured, Front, Reference, Current };
        std::vector<std::pair<Swatch, std::string>> entries;
        const auto any = [&](auto predicate) {
            return std::any_of(drawable_.begin(), drawable_.end(), predicate);
        };
        if (any([&](std::size_t i) { return !point(i).isReference && !point(i).isCurrent; }))
            entries.push_back({Swatch::Measured, "measured setting"});
        if (front_.size() >= 2) entries.push_back({Swatch::Front, "Pareto front"});
        if (any([&](std::size_t i) { return point(i).isReference; }))
            entries.push_back({Swatch::Reference, "reference"});
        if (any([&](std::size_t i) { return point(i).isCurrent; }))
            entries.push_back({Swatch::Current, "current"});
        if (entries.empty()) return;

        const double entryHeight = rowHeight_ + 10.0, swatchWidth = 30.0, pad = 10.0, inset = 10.0;
        double textWidth = 0.0;
        for (const auto& entry : entries)
            textWidth = std::max(textWidth, measureText(entry.second, kTextScale).width);
        const double w = pad + swatchWidth + 10.0 + textWidth + pad;
        const double h = 2.0 * pad + entryHeight * static_cast<double>(entries.size()) - 10.0;
        const double left = layout_.left + inset, right = layout_.right - inset;
        const double top = layout_.top + inset, bottom = layout_.bottom - inset;
        const std::array<Box, 4> corners = {
            Box{right - w, top, right, top + h}, Box{left, top, left + w, top + h},
            Box{right - w, bottom - h, right, bottom}, Box{left, bottom - h, left + w, bottom}};
        const Box box = leastCrowded(corners, 6.0);  // with clearance, so it does not touch a marker

        canvas_.fillRect(box.x0, box.y0, box.x1, box.y1, kBackground);
        canvas_.strokeRect(box.x0, box.y0, box.x1, box.y1, 1.0, kGrid);
        for (std::size_t row = 0; row < entries.size(); ++row) {
            const double cy = box.y0 + pad + static_cast<double>(row) * entryHeight + rowHeight_ / 2.0;
            const double cx = box.x0 + pad + swatchWidth / 2.0;
            switch (entries[row].first) {
                case Swatch::Measured:
                    drawMarker(canvas_, PlotPoint{}, cx, cy);
                    break;
                case Swatch::Front:
                    canvas_.drawLine(cx - swatchWidth / 2.0, cy, cx + swatchWidth / 2.0, cy, kFrontThickness,
                                     kParetoFront);
                    break;
                case Swatch::Reference:
                    drawMarker(canvas_, PlotPoint{"", 0, 0, true, false}, cx, cy);
                    break;
                case Swatch::Current:
                    drawMarker(canvas_, PlotPoint{"", 0, 0, false, true}, cx, cy);
                    break;
            }
            drawText(canvas_, box.x0 + pad + swatchWidth + 10.0, cy - rowHeight_ / 2.0 + 1.0,
                     entries[row].second, kTextScale, kInk);
        }
        obstacles_.push_back(box);
    }

    // The special points choose first, then the front, then the rest; each label takes the spot
    // around its marker that hides the least of what is already there.
    void drawPointLabels() {
        std::vector<std::size_t> order(drawOrder_.rbegin(), drawOrder_.rend());
        std::stable_partition(order.begin(), order.end(), [&](std::size_t i) {
            return point(i).isReference || point(i).isCurrent ||
                   std::find(front_.begin(), front_.end(), i) != front_.end();
        });
        for (std::size_t i : order) {
            const std::string text = displayLabel(point(i));
            if (text.empty()) continue;
            const TextSize size = measureText(text, kTextScale);
            const double px = pixels_[i][0], py = pixels_[i][1], r = markerRadius(point(i)) + 5.0;
            const double w = size.width, h = size.height, d = r * 0.6;
            const std::array<Box, 8> candidates = {
                Box{px + r, py - h / 2, px + r + w, py + h / 2},  // right
                Box{px - r - w, py - h / 2, px - r, py + h / 2},  // left
                Box{px + d, py - r - h, px + d + w, py - r},      // above right
                Box{px + d, py + r, px + d + w, py + r + h},      // below right
                Box{px - d - w, py - r - h, px - d, py - r},      // above left
                Box{px - d - w, py + r, px - d, py + r + h},      // below left
                Box{px - w / 2, py - r - h, px + w / 2, py - r},  // above
                Box{px - w / 2, py + r, px + w / 2, py + r + h},  // below
            };
            const Box best = leastCrowded(candidates, 0.0);
            drawText(canvas_, best.x0, best.y0 + 1.0, text, kTextScale, point(i).isCurrent ? kCurrent : kInk);
            obstacles_.push_back(best);
        }
    }

    void drawNotes() {
        double y = layout_.notesTop;
        for (const std::string& note : layout_.notes) {
            drawText(canvas_, kMargin, y, note, kTextScale, kNote);
            y += rowHeight_ + kNoteSpacing;
        }
    }

    const ScatterPlot& plot_;
    const PlotLayout layout_;
    Canvas canvas_;
    const double rowHeight_;
    std::vector<PixelPoint> pixels_;       // per point, valid for drawable ones
    std::vector<std::size_t> drawable_;    // points with finite coordinates
    std::vector<std::size_t> drawOrder_;   // drawable points, special ones last
    std::vector<std::size_t> front_;       // Pareto front, by increasing x
    std::vector<Box> obstacles_;           // what text should not cover
    std::vector<PixelPoint> lineSamples_;  // points along the lines text should not cross
};

}  // namespace

ByteImage renderScatterPlot(const ScatterPlot& plot, int width, int height) {
    return ScatterPlotPainter(plot, width, height).paint();
}

}  // namespace fx
