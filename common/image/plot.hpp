#pragma once
// The benchmark's picture: error against time for every quality setting of an effect, drawn on
// the CPU into an image a person would rather look at than read a table.
//
// What it shows: every measured setting as a disc with its label; the reference setting as a
// diamond labelled "(reference)"; the setting in use now in red with a ring; a measured spread in x
// (min to max over repeated measurements) as a bar with end caps through the marker; the Pareto
// front (the settings no other setting beats in both time and error, counting two times whose
// spreads overlap as equal) joined by an orange line; axes with ticks on nice numbers, x on a log
// scale when the data span a factor of 20 or more, a title, axis labels and a legend. Labels never
// overlap each other or a marker: a label with no free spot is left out (the table has every row).
//
// Awkward input still gives a picture, with a grey note in the bottom-left corner saying what was
// done: no points (an empty frame saying so), one point or equal x values (a range around them),
// y <= 0 on a logarithmic axis (drawn at a floor a decade below the smallest positive y, which is
// where the reference's error of 0 lands), no positive y at all (a linear axis instead), and NaN or
// infinite values (the point is left out and named).
#include <algorithm>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "image/canvas.hpp"
#include "image/image.hpp"
#include "image/plot_axis.hpp"

namespace fx {

struct PlotPoint {
    std::string label;
    double x = 0.0, y = 0.0;
    bool isReference = false;
    bool isCurrent = false;
    // The spread of x over repeated measurements; both 0 (or equal to x) when there is none.
    double xLow = 0.0, xHigh = 0.0;

    bool hasSpread() const { return xHigh > xLow; }
    double lowX() const { return hasSpread() ? std::min(xLow, x) : x; }
    double highX() const { return hasSpread() ? std::max(xHigh, x) : x; }
};

struct ScatterPlot {
    std::string title, xLabel, yLabel;
    std::vector<PlotPoint> points;
    bool logY = false;
    // Unset: logarithmic when every x is positive and the largest is 20 times the smallest or more
    // (a reference 50 times slower than the settings would squeeze them into one column).
    std::optional<bool> logX;
    // Grey lines under the plot, after the ones the layout adds (groupEqualCosts says what it grouped).
    std::vector<std::string> notes;
};

// Settings whose costs cannot be told apart show as such. Points whose x spreads overlap (chained in
// order of cost) are drawn at one cost, the median of theirs, with the spread of all of them, so their
// left-to-right order is no longer the noise of a few frames; of those, points with the same error
// (to a part in a million) become one marker labelled with every setting in the order they are given
// (the knob's values: "16 = 32 = 64"), instead of markers stacked on one spot with one label showing.
// A note names each group. Points without a spread group only with equal x. The bench's picture and
// the overlay's cost panel both draw the grouped plot.
ScatterPlot groupEqualCosts(const ScatterPlot& plot);

// True when positive data from `low` to `high` call for a logarithmic axis (high >= 20 low).
bool wantsLogAxis(double low, double high);

// The colours a reader (and a test) can rely on.
namespace plot_colours {
inline constexpr Rgba kBackground{255, 255, 255, 255};
inline constexpr Rgba kInk{40, 40, 40, 255};  // axes, text, the reference marker
inline constexpr Rgba kGrid{226, 226, 226, 255};
inline constexpr Rgba kPoint{52, 101, 164, 255};       // blue
inline constexpr Rgba kCurrent{204, 0, 0, 255};        // red
inline constexpr Rgba kParetoFront{245, 121, 0, 255};  // orange
inline constexpr Rgba kNote{110, 110, 110, 255};
inline constexpr Rgba kSpread{150, 165, 190, 255};  // the min-max bar behind a marker
}  // namespace plot_colours

// Where things go on the canvas (pixels, y growing downwards), computed once and used both to draw
// and to test the drawing.
struct PlotLayout {
    double left = 0, top = 0, right = 0, bottom = 0;  // the framed plot area
    double xLabelTop = 0, notesTop = 0;               // where the x-axis label and the notes start
    PlotAxis xAxis, yAxis;
    double yFloor = 0.0;  // on a log axis, y values below this are drawn at it; 0 when unused
    std::vector<std::string> notes;

    bool isDrawable(const PlotPoint& point) const;  // finite x and y
    double pixelX(double x) const;
    double pixelY(double y) const;  // applies the floor
};

PlotLayout layoutScatterPlot(const ScatterPlot& plot, int width, int height);

// Indices of the drawable points on the Pareto front, ordered by increasing x. Built from the most
// accurate point (lowest y; the cheaper of equals) down: a point joins when its whole x spread is
// below the spread of the last point that joined, i.e. when it is clearly cheaper for its larger
// error. Neighbours on the front therefore always differ in cost by more than their spreads, and a
// point whose cost cannot be told from a more accurate one's is off it. Without spreads this is the
// usual front. Of several identical points only one is listed.
std::vector<std::size_t> paretoFront(const std::vector<PlotPoint>& points);

// A box in pixels, y growing downwards.
struct PlotBox {
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    double overlap(const PlotBox& o) const;  // the area both cover
    PlotBox grownBy(double d) const { return {x0 - d, y0 - d, x1 + d, y1 + d}; }
};

// A label to put next to a marker at (x, y) whose drawing reaches `radius` pixels from its centre.
struct LabelRequest {
    double x = 0, y = 0, radius = 0;
    double width = 0, height = 0;  // of the text
};

// Places labels in order (put the important ones first): each takes, of eight spots around its
// marker, then the same eight farther out (three more rings), one inside `area` that overlaps no marker box
// and no label placed before it, the one with the lowest `cost` (optional: what else it would hide). A label
// with no such spot gets none. The bench's picture and the overlay's cost panel both place labels so.
// The leader line from a marker to its label, for a label placed away from its marker (nothing when
// it sits next to it): x0, y0 just outside the marker, x1, y1 on the label's nearest edge.
std::optional<PlotBox> labelLeader(const LabelRequest& label, const PlotBox& box);

std::vector<std::optional<PlotBox>> placeLabels(const std::vector<LabelRequest>& labels,
                                                const std::vector<PlotBox>& markers, const PlotBox& area,
                                                const std::function<double(const PlotBox&)>& cost = {});

// RGBA, bottom-up like every ByteImage, of the plot with its equal costs grouped (groupEqualCosts).
// `labels`, when given, receives the box of every label drawn.
ByteImage renderScatterPlot(const ScatterPlot& plot, int width = 960, int height = 600,
                            std::vector<PlotBox>* labels = nullptr);

}  // namespace fx
