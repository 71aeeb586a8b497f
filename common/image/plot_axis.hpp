#pragma once
// Plot axes: which range an axis shows, where its ticks go and how their labels read.
//
// Ticks fall on "nice" numbers, 1, 2 or 5 times a power of ten, so a reader can interpolate in
// their head. A logarithmic axis puts ticks on powers of ten (only every second, third, ... power
// when the range is wide, with 2 and 5 in between when it spans three decades or fewer).
#include <string>
#include <vector>

namespace fx {

struct PlotAxis {
    double low = 0.0, high = 1.0;  // the values at the two ends of the axis (low < high)
    bool logarithmic = false;
    std::vector<double> ticks;  // values, ascending, all within [low, high]
    std::vector<std::string> tickLabels;

    // Where a value falls along the axis: 0 at `low`, 1 at `high` (outside for values beyond).
    double fraction(double value) const;
};

// The nice number (1, 2 or 5 times a power of ten) closest to `roughStep`, which must be > 0.
double niceStep(double roughStep);

// A linear axis that shows [dataMin, dataMax] with a little room at both ends and about
// `targetTicks` ticks. Equal ends (a single value) get a range around the value.
PlotAxis makeLinearAxis(double dataMin, double dataMax, int targetTicks = 6);

// A logarithmic axis for positive data; both values must be > 0.
PlotAxis makeLogAxis(double dataMin, double dataMax);

// A tick label: "0.25", "1500", "1e-06"; `step` is the spacing of the neighbouring ticks.
std::string formatTick(double value, double step);

// Any value in at most three significant digits: "0.00021", "1.5e-7", "1.23e6".
std::string formatValue(double value);

}  // namespace fx
