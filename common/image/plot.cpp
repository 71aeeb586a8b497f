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

using Box = PlotBox;

bool contains(const Box& b, const PixelPoint& p) {
    return p[0] >= b.x0 && p[0] <= b.x1 && p[1] >= b.y0 && p[1] <= b.y1;
}
double area(const Box& b) {
    return (b.x1 - b.x0) * (b.y1 - b.y0);
}

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

        // A spread: a thin bar from the smallest to the largest measurement, with end caps, under the marker.
        for (std::size_t i : drawable_) {
            const PlotPoint& p = point(i);
            if (!p.hasSpread()) continue;
            const double x0 = layout_.pixelX(p.lowX()), x1 = layout_.pixelX(p.highX()), y = pixels_[i][1];
            canvas_.fillRect(x0, y - 1.0, x1, y + 1.0, kSpread);
            canvas_.fillRect(x0 - 1.0, y - 6.0, x0 + 1.0, y + 6.0, kSpread);
            canvas_.fillRect(x1 - 1.0, y - 6.0, x1 + 1.0, y + 6.0, kSpread);
            obstacles_.push_back({x0 - 1.0, y - 6.0, x1 + 1.0, y + 6.0});  // labels keep off the bar
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
            if (contains(box, sample)) cost += 16.0;
        const Box plotArea{layout_.left, layout_.top, layout_.right, layout_.bottom};
        cost += (area(box) - box.overlap(plotArea)) * 4.0;
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

    // The special points choose first, then the front, then the rest; each label takes a free spot
    // around its marker that crosses the fewest lines (placeLabels), or is left out.
    void drawPointLabels() {
        std::vector<std::size_t> order(drawOrder_.rbegin(), drawOrder_.rend());
        std::stable_partition(order.begin(), order.end(), [&](std::size_t i) {
            return point(i).isReference || point(i).isCurrent ||
                   std::find(front_.begin(), front_.end(), i) != front_.end();
        });
        std::vector<std::size_t> labelled;
        std::vector<LabelRequest> requests;
        for (std::size_t i : order) {
            const std::string text = displayLabel(point(i));
            if (text.empty()) continue;
            const TextSize size = measureText(text, kTextScale);
            labelled.push_back(i);
            requests.push_back(
                {pixels_[i][0], pixels_[i][1], markerRadius(point(i)), size.width, size.height});
        }
        const Box plotArea{layout_.left + 2.0, layout_.top + 2.0, layout_.right - 2.0, layout_.bottom - 2.0};
        const auto boxes =
            placeLabels(requests, obstacles_, plotArea, [&](const Box& box) { return crowding(box); });
        // Points left without a label are named in one line, left to right, where it hides nothing.
        std::vector<std::size_t> unlabelled;
        for (std::size_t k = 0; k < labelled.size(); ++k)
            if (!boxes[k]) unlabelled.push_back(labelled[k]);
        std::sort(unlabelled.begin(), unlabelled.end(),
                  [&](std::size_t a, std::size_t b) { return pixels_[a][0] < pixels_[b][0]; });
        if (!unlabelled.empty()) {
            std::string line = "left to right:";
            for (std::size_t n = 0; n < unlabelled.size(); ++n)
                line += (n ? ", " : " ") + displayLabel(point(unlabelled[n]));
            const TextSize size = measureText(line, kTextScale);
            std::vector<Box> taken = obstacles_;
            for (const auto& b : boxes)
                if (b) taken.push_back(*b);
            // Rows down the left and right of the plot area: the free one that crosses the fewest lines.
            const double inset = 8.0;
            std::optional<Box> best;
            double bestCost = 0.0;
            for (double y = layout_.bottom - inset - size.height; y >= layout_.top + inset;
                 y -= size.height / 2.0) {
                for (double x : {layout_.left + inset, layout_.right - inset - size.width}) {
                    const Box spot{x, y, x + size.width, y + size.height};
                    if (spot.x0 < layout_.left || std::any_of(taken.begin(), taken.end(), [&](const Box& t) {
                            return spot.grownBy(2.0).overlap(t) > 0;
                        }))
                        continue;
                    const double cost = crowding(spot);
                    if (!best || cost < bestCost) best = spot, bestCost = cost;
                }
            }
            if (best) {
                drawText(canvas_, best->x0, best->y0 + 1.0, line, kTextScale, kNote);
                labelBoxes_.push_back(*best);
            }
        }
        for (std::size_t k = 0; k < labelled.size(); ++k) {
            if (!boxes[k]) continue;
            const std::size_t i = labelled[k];
            // A label that had to move away from its marker gets a thin line back to it.
            const Box& b = *boxes[k];
            if (auto leader = labelLeader(requests[k], b))
                canvas_.drawLine(leader->x0, leader->y0, leader->x1, leader->y1, 1.0, kNote);
            drawText(canvas_, b.x0, b.y0 + 1.0, displayLabel(point(i)), kTextScale,
                     point(i).isCurrent ? kCurrent : kInk);
            labelBoxes_.push_back(*boxes[k]);
        }
    }

public:
    const std::vector<Box>& labelBoxes() const { return labelBoxes_; }

private:
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
    std::vector<Box> labelBoxes_;          // the point labels drawn
};

}  // namespace

ByteImage renderScatterPlot(const ScatterPlot& plot, int width, int height, std::vector<PlotBox>* labels) {
    const ScatterPlot grouped = groupEqualCosts(plot);
    ScatterPlotPainter painter(grouped, width, height);
    ByteImage image = painter.paint();
    if (labels) *labels = painter.labelBoxes();
    return image;
}

}  // namespace fx
