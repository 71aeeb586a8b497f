#include "image/plot.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "base/log.hpp"
#include "image/plot_style.hpp"

namespace fx {
namespace {

using namespace plot_style;

// A note that ends in a list of names, "prefix: a, b, c", cut short so that it fits on one line of
// a picture `width` pixels wide.
std::string noteWithNames(const std::string& prefix, const std::vector<std::string>& names, int width) {
    const double charWidth = measureText("0", kTextScale).width + kTextScale;  // advance per character
    const auto fits = [&](const std::string& text) {
        return measureText(text, kTextScale).width <= width - 2.0 * kMargin - 4.0 * charWidth;
    };
    std::string note = prefix + ": ";
    for (std::size_t i = 0; i < names.size(); ++i) {
        const std::string name = names[i].empty() ? std::string("(unnamed)") : names[i];
        const std::string next = note + (i > 0 ? ", " : "") + name;
        if (!fits(next))
            return i > 0 ? note + ", ..." : cat(note, names.size(), names.size() == 1 ? " point" : " points");
        note = next;
    }
    return note;
}

}  // namespace

bool PlotLayout::isDrawable(const PlotPoint& point) const {
    return std::isfinite(point.x) && std::isfinite(point.y);
}

double PlotLayout::pixelX(double x) const {
    return left + xAxis.fraction(x) * (right - left);
}

double PlotLayout::pixelY(double y) const {
    if (yAxis.logarithmic && yFloor > 0.0 && !(y >= yFloor)) y = yFloor;
    return bottom - yAxis.fraction(y) * (bottom - top);
}

std::vector<std::size_t> paretoFront(const std::vector<PlotPoint>& points) {
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < points.size(); ++i)
        if (std::isfinite(points[i].x) && std::isfinite(points[i].y)) order.push_back(i);
    // The most accurate first (the cheaper of equals); then each point joins when it is clearly
    // cheaper than the last one that joined: its whole spread below that one's.
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        if (points[a].y != points[b].y) return points[a].y < points[b].y;
        return points[a].x < points[b].x;
    });
    std::vector<std::size_t> front;
    for (std::size_t i : order) {
        if (front.empty() || points[i].highX() < points[front.back()].lowX()) front.push_back(i);
    }
    std::reverse(front.begin(), front.end());  // by increasing x
    return front;
}

ScatterPlot groupEqualCosts(const ScatterPlot& plot) {
    ScatterPlot out = plot;
    out.points.clear();
    const std::vector<PlotPoint>& in = plot.points;
    std::vector<std::size_t> byCost;
    for (std::size_t i = 0; i < in.size(); ++i)
        if (std::isfinite(in[i].x) && std::isfinite(in[i].y)) byCost.push_back(i);
    std::stable_sort(byCost.begin(), byCost.end(),
                     [&](std::size_t a, std::size_t b) { return in[a].x < in[b].x; });
    // Runs of points each of which reaches the spread of the run so far.
    std::vector<std::vector<std::size_t>> groups;
    double reach = 0.0;
    for (std::size_t i : byCost) {
        if (!groups.empty() && in[i].lowX() <= reach) {
            groups.back().push_back(i);
        } else {
            groups.push_back({i});
        }
        reach = groups.back().size() == 1 ? in[i].highX() : std::max(reach, in[i].highX());
    }
    std::vector<std::pair<std::size_t, PlotPoint>> shown;  // first member's index, the point drawn
    for (std::vector<std::size_t>& group : groups) {
        std::sort(group.begin(), group.end());  // the order the points were given in
        std::vector<double> xs;
        double low = in[group.front()].lowX(), high = in[group.front()].highX();
        for (std::size_t i : group) {
            xs.push_back(in[i].x);
            low = std::min(low, in[i].lowX()), high = std::max(high, in[i].highX());
        }
        std::sort(xs.begin(), xs.end());
        const double x =
            xs.size() % 2 ? xs[xs.size() / 2] : 0.5 * (xs[xs.size() / 2 - 1] + xs[xs.size() / 2]);
        std::vector<std::string> labels;
        for (std::size_t i : group) labels.push_back(in[i].label);
        // Of the group, those with one error are one marker.
        std::vector<bool> merged(group.size(), false);
        for (std::size_t a = 0; a < group.size(); ++a) {
            if (merged[a]) continue;
            PlotPoint p = in[group[a]];
            for (std::size_t b = a + 1; b < group.size(); ++b) {
                const PlotPoint& q = in[group[b]];
                if (merged[b] || std::abs(q.y - p.y) > 1e-6 * std::max(std::abs(p.y), 1e-12)) continue;
                merged[b] = true;
                p.label += " = " + q.label;
                p.isReference = p.isReference || q.isReference;
                p.isCurrent = p.isCurrent || q.isCurrent;
            }
            if (group.size() > 1) p.x = x, p.xLow = low, p.xHigh = high;
            shown.emplace_back(group[a], p);
        }
        if (group.size() > 1) {
            std::string names;
            for (const std::string& l : labels) names += (names.empty() ? "" : ", ") + l;
            out.notes.push_back(cat("same cost within the spread, drawn at one: ", names));
        }
    }
    std::sort(shown.begin(), shown.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (auto& [index, point] : shown) out.points.push_back(std::move(point));
    // What cannot be drawn stays, for the layout to name.
    for (const PlotPoint& p : in)
        if (!(std::isfinite(p.x) && std::isfinite(p.y))) out.points.push_back(p);
    return out;
}

bool wantsLogAxis(double low, double high) {
    return low > 0.0 && std::isfinite(high) && high >= 20.0 * low;
}

double PlotBox::overlap(const PlotBox& o) const {
    const double w = std::min(x1, o.x1) - std::max(x0, o.x0), h = std::min(y1, o.y1) - std::max(y0, o.y0);
    return w > 0 && h > 0 ? w * h : 0.0;
}

std::optional<PlotBox> labelLeader(const LabelRequest& l, const PlotBox& box) {
    const double nx = std::clamp(l.x, box.x0, box.x1), ny = std::clamp(l.y, box.y0, box.y1);
    const double d = std::hypot(nx - l.x, ny - l.y);
    if (d <= l.radius + 12.0) return std::nullopt;
    // From just outside the marker (its own box is no obstacle) to the label's nearest edge.
    const double start = (l.radius + 2.0) / d;
    return PlotBox{l.x + (nx - l.x) * start, l.y + (ny - l.y) * start, nx, ny};
}

std::vector<std::optional<PlotBox>> placeLabels(const std::vector<LabelRequest>& labels,
                                                const std::vector<PlotBox>& markers, const PlotBox& area,
                                                const std::function<double(const PlotBox&)>& cost) {
    std::vector<std::optional<PlotBox>> placed;
    std::vector<PlotBox> taken = markers;
    for (const LabelRequest& l : labels) {
        std::optional<PlotBox> best;
        double bestCost = 0.0;
        for (double reach : {1.0, 2.2, 3.4, 4.6}) {
            const double px = l.x, py = l.y, r = (l.radius + 4.0) * reach, w = l.width, h = l.height;
            const double d = r * 0.6;
            const PlotBox candidates[] = {
                {px + r, py - h / 2, px + r + w, py + h / 2},  // right
                {px - r - w, py - h / 2, px - r, py + h / 2},  // left
                {px + d, py - r - h, px + d + w, py - r},      // above right
                {px + d, py + r, px + d + w, py + r + h},      // below right
                {px - d - w, py - r - h, px - d, py - r},      // above left
                {px - d - w, py + r, px - d, py + r + h},      // below left
                {px - w / 2, py - r - h, px + w / 2, py - r},  // above
                {px - w / 2, py + r, px + w / 2, py + r + h},  // below
            };
            for (const PlotBox& c : candidates) {
                if (c.x0 < area.x0 || c.x1 > area.x1 || c.y0 < area.y0 || c.y1 > area.y1) continue;
                const PlotBox padded = c.grownBy(1.0);
                if (std::any_of(taken.begin(), taken.end(),
                                [&](const PlotBox& t) { return padded.overlap(t) > 0; }))
                    continue;
                // Away from its marker a label gets a leader line: it must cross no marker and no label.
                if (auto leader = labelLeader(l, c)) {
                    bool crosses = false;
                    for (int i = 0; i <= 16 && !crosses; ++i) {
                        const double x = leader->x0 + (leader->x1 - leader->x0) * i / 16.0;
                        const double y = leader->y0 + (leader->y1 - leader->y0) * i / 16.0;
                        const PlotBox dot{x - 0.5, y - 0.5, x + 0.5, y + 0.5};
                        crosses = std::any_of(taken.begin(), taken.end(),
                                              [&](const PlotBox& t) { return dot.overlap(t) > 0; });
                    }
                    if (crosses) continue;
                }
                const double k = cost ? cost(c) : 0.0;
                if (!best || k < bestCost) best = c, bestCost = k;
            }
            if (best) break;  // the near ring had a free spot
        }
        if (best) taken.push_back(*best);
        placed.push_back(best);
    }
    return placed;
}

PlotLayout layoutScatterPlot(const ScatterPlot& plot, int width, int height) {
    PlotLayout layout;
    const double rowHeight = lineHeight();

    double minX = std::numeric_limits<double>::infinity(), maxX = -minX, minY = minX, maxY = -minX;
    double minPositiveY = minX;
    std::vector<std::string> skipped, floored;
    for (const PlotPoint& point : plot.points) {
        if (!layout.isDrawable(point)) {
            skipped.push_back(point.label);
            continue;
        }
        minX = std::min(minX, point.lowX()), maxX = std::max(maxX, point.highX());
        minY = std::min(minY, point.y), maxY = std::max(maxY, point.y);
        if (point.y > 0.0) minPositiveY = std::min(minPositiveY, point.y);
        if (point.y <= 0.0) floored.push_back(displayLabel(point));
    }
    const bool hasData = minX <= maxX;
    if (!hasData) {
        minX = minY = 0.0;
        maxX = maxY = 1.0;
        layout.notes.push_back("no points to plot");
    }
    if (!skipped.empty())
        layout.notes.push_back(noteWithNames("not drawn (NaN or infinite values)", skipped, width));
    for (const std::string& note : plot.notes) layout.notes.push_back(note);
    bool logY = plot.logY && hasData;
    if (logY && !(minPositiveY <= maxY)) {
        logY = false;
        layout.notes.push_back("no y above 0, which a log scale needs: linear scale used");
    }

    const bool logX = hasData && minX > 0.0 && plot.logX.value_or(wantsLogAxis(minX, maxX));
    if (hasData && plot.logX.value_or(false) && !logX)
        layout.notes.push_back("x <= 0, which a log scale cannot show: linear scale used");

    // Vertical extent first: it decides how many y ticks fit, and their labels decide the left margin.
    // Below the frame, top to bottom: tick marks, tick labels, the x-axis label, the notes.
    const std::size_t noteCount = layout.notes.size() + (logY && !floored.empty() ? 1 : 0);
    layout.top = plot.title.empty() ? kMargin + 8.0 : kMargin + measureText("0", kTitleScale).height + 22.0;
    const double belowFrame = kTickLength + kTickLabelGap + rowHeight + kLabelGap +
                              (plot.xLabel.empty() ? 0.0 : rowHeight + kLabelGap) +
                              static_cast<double>(noteCount) * (rowHeight + kNoteSpacing);
    layout.bottom = std::max(layout.top + 1.0, height - kMargin - belowFrame);
    layout.xLabelTop = layout.bottom + kTickLength + kTickLabelGap + rowHeight + kLabelGap;
    layout.notesTop = layout.xLabelTop + (plot.xLabel.empty() ? 0.0 : rowHeight + kLabelGap);
    const int yTicks = std::clamp(static_cast<int>((layout.bottom - layout.top) / 70.0), 2, 8);

    if (logY) {
        if (!floored.empty()) {
            layout.yFloor = minPositiveY / 10.0;
            layout.notes.push_back(noteWithNames(
                cat("y <= 0 drawn at ", formatValue(layout.yFloor), " on the log scale"), floored, width));
        }
        layout.yAxis = makeLogAxis(layout.yFloor > 0.0 ? layout.yFloor : minPositiveY, maxY);
    } else {
        layout.yAxis = makeLinearAxis(minY, maxY, yTicks);
    }

    double widestTick = 0.0;
    for (const std::string& label : layout.yAxis.tickLabels)
        widestTick = std::max(widestTick, measureText(label, kTextScale).width);
    layout.left = kMargin + (plot.yLabel.empty() ? 0.0 : rowHeight + kLabelGap) + widestTick + kTickLabelGap +
                  kTickLength;
    layout.right = std::max(layout.left + 1.0, width - kMargin - 20.0);  // room for half a tick label
    const int xTicks = std::clamp(static_cast<int>((layout.right - layout.left) / 120.0), 2, 10);
    layout.xAxis = logX ? makeLogAxis(minX, maxX) : makeLinearAxis(minX, maxX, xTicks);
    return layout;
}

}  // namespace fx
