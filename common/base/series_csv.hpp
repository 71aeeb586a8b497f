#pragma once
// Curves for a line plot, read from a CSV table of measurements: one row per run, with a column for
// x, one naming the series the row belongs to and one or more whose sum is y. Rows of one series at
// one x are repeated runs; a curve goes through their median, which one slow run (the machine busy
// with something else for a moment) does not move. The bench scripts in tools/bench write such
// tables and tools/bench/series_plot.cpp draws them.
#include <string>
#include <string_view>
#include <vector>

#include "base/result.hpp"

namespace fx {

struct SeriesPoint {
    double x = 0.0, y = 0.0;  // y: the median of the runs at this x
    int runs = 0;
};

struct Series {
    std::string name;
    std::vector<SeriesPoint> points;  // by increasing x
};

// Column names in the table's header line. y lists the columns added up to give a row's y (the
// lighting pass plus the culling pass that feeds it, say).
struct SeriesColumns {
    std::string x, series;
    std::vector<std::string> y;
};

// One CSV line's fields. A field in double quotes may hold commas, and "" inside it is one quote.
std::vector<std::string> splitCsvLine(std::string_view line);

// The middle value, or the mean of the two middle ones; values must not be empty.
double median(std::vector<double> values);

// The series in the order their names first appear in the table. Errors name `source` (the file), the
// line and the column: a missing column, a row with fewer fields than the header, a value that is not a
// finite number, a table with no rows. Empty lines are skipped.
Result<std::vector<Series>> readSeriesCsv(std::string_view text, const SeriesColumns& columns,
                                          std::string_view source);

}  // namespace fx
