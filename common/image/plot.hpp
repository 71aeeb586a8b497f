#pragma once
// The benchmark's picture: error against time for every quality setting of an effect, drawn on
// the CPU into an image a person would rather look at than read a table.
//
// What it shows: every measured setting as a disc with its label; the reference setting as a
// diamond labelled "(reference)"; the setting in use now in red with a ring; the Pareto front
// (the settings no other setting beats in both time and error) joined by an orange line; axes
// with ticks on nice numbers, a title, axis labels and a legend.
//
// Awkward input still gives a picture, with a grey note in the bottom-left corner saying what was
// done: no points (an empty frame saying so), one point or equal x values (a range around them),
// y <= 0 on a logarithmic axis (drawn at a floor a decade below the smallest positive y, which is
// where the reference's error of 0 lands), no positive y at all (a linear axis instead), and NaN or
// infinite values (the point is left out and named).
#include <cstddef>
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
};

struct ScatterPlot {
    std::string title, xLabel, yLabel;
    std::vector<PlotPoint> points;
    bool logY = false;
};

// The colours a reader (and a test) can rely on.
namespace plot_colours {
inline constexpr Rgba kBackground{255, 255, 255, 255};
inline constexpr Rgba kInk{40, 40, 40, 255};  // axes, text, the reference marker
inline constexpr Rgba kGrid{226, 226, 226, 255};
inline constexpr Rgba kPoint{52, 101, 164, 255};       // blue
inline constexpr Rgba kCurrent{204, 0, 0, 255};        // red
inline constexpr Rgba kParetoFront{245, 121, 0, 255};  // orange
inline constexpr Rgba kNote{110, 110, 110, 255};
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

// Indices of the drawable points on the Pareto front, ordered by increasing x. A point is on the
// front when no other point has x and y both at most its own and one of them strictly smaller.
// Of several identical points only one is listed.
std::vector<std::size_t> paretoFront(const std::vector<PlotPoint>& points);

// RGBA, bottom-up like every ByteImage.
ByteImage renderScatterPlot(const ScatterPlot& plot, int width = 960, int height = 600);

}  // namespace fx
