// A bench sweep as a picture: one line per series through the median y of its runs at each x, both
// axes logarithmic (costs that grow with a count read as slopes: 1 is linear), from a CSV table of
// runs (base/series_csv.hpp). With --copy-ms the y ticks also read in full-screen copies of the run
// that measured them, the bench's unit. It prints the medians as well.
//   fx_series_plot light_sweep.csv out.png --x lights --series culling --y lighting_ms+culling_ms
//       --title "..." --x-label "point lights" --y-label "ms"
// tools/bench/lesson07_paths_plot.sh and lesson10_light_sweep.sh call it.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "base/file_io.hpp"
#include "base/series_csv.hpp"
#include "image/canvas.hpp"
#include "image/canvas_text.hpp"
#include "image/plot.hpp"
#include "image/plot_axis.hpp"
#include "image/png_file.hpp"

namespace {

using namespace fx;

struct Options {
    std::string csv, png, title, xLabel, yLabel = "ms", legend;  // legend: a heading over the names
    SeriesColumns columns;
    double copyMs = 0.0;  // 0: no copies on the y ticks
};

// "a+b+c" -> {"a", "b", "c"}
std::vector<std::string> splitPlus(const std::string& text) {
    std::vector<std::string> out(1);
    for (char c : text)
        if (c == '+')
            out.emplace_back();
        else
            out.back() += c;
    return out;
}

bool parseArguments(int argc, char** argv, Options& o) {
    std::vector<std::string> positional;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a.rfind("--", 0) != 0) {
            positional.push_back(a);
            continue;
        }
        if (i + 1 >= argc) {
            std::fprintf(stderr, "%s needs a value\n", a.c_str());
            return false;
        }
        const std::string v = argv[++i];
        if (a == "--x")
            o.columns.x = v;
        else if (a == "--series")
            o.columns.series = v;
        else if (a == "--y")
            o.columns.y = splitPlus(v);
        else if (a == "--title")
            o.title = v;
        else if (a == "--x-label")
            o.xLabel = v;
        else if (a == "--y-label")
            o.yLabel = v;
        else if (a == "--legend")
            o.legend = v;
        else if (a == "--copy-ms") {
            char* end = nullptr;
            o.copyMs = std::strtod(v.c_str(), &end);
            if (*end != '\0' || !(o.copyMs > 0.0) || !std::isfinite(o.copyMs)) {
                std::fprintf(stderr, "--copy-ms: '%s' is not a time above 0\n", v.c_str());
                return false;
            }
        } else {
            std::fprintf(stderr, "unknown option %s\n", a.c_str());
            return false;
        }
    }
    if (positional.size() != 2 || o.columns.x.empty() || o.columns.series.empty() || o.columns.y.empty()) {
        std::fprintf(
            stderr,
            "usage: fx_series_plot CSV PNG --x COLUMN --series COLUMN --y COLUMN[+COLUMN...]\n"
            "       [--title TEXT] [--x-label TEXT] [--y-label TEXT] [--legend TEXT] [--copy-ms MS]\n");
        return false;
    }
    o.csv = positional[0];
    o.png = positional[1];
    if (o.xLabel.empty()) o.xLabel = o.columns.x;
    return true;
}

// Red, blue and orange as the bench's scatter plot uses them, then green, purple, brown.
const Rgba kLineColours[] = {plot_colours::kCurrent, plot_colours::kPoint, plot_colours::kParetoFront,
                             {78, 154, 6, 255},      {117, 80, 123, 255},  {143, 89, 2, 255}};

ByteImage draw(const Options& o, const std::vector<Series>& series) {
    double minX = 1e300, maxX = 0, minY = 1e300, maxY = 0;
    std::set<double> xs;
    int mostRuns = 0, fewestRuns = 1 << 30;
    for (const Series& s : series)
        for (const SeriesPoint& p : s.points) {
            minX = std::min(minX, p.x), maxX = std::max(maxX, p.x);
            minY = std::min(minY, p.y), maxY = std::max(maxY, p.y);
            xs.insert(p.x);
            mostRuns = std::max(mostRuns, p.runs), fewestRuns = std::min(fewestRuns, p.runs);
        }
    const PlotAxis xAxis = makeLogAxis(minX, maxX), yAxis = makeLogAxis(minY, maxY);
    // A sweep has few x values: ticks on them read better than on powers of ten.
    std::vector<double> xTicks(xs.begin(), xs.end());
    std::vector<std::string> xTickLabels;
    for (double x : xTicks)  // counts in full: "100000" rather than "1e5"
        xTickLabels.push_back(x == std::round(x) && x < 1e7 ? std::to_string(static_cast<long>(x))
                                                            : formatValue(x));
    if (xTicks.size() > 10) xTicks = xAxis.ticks, xTickLabels = xAxis.tickLabels;
    std::vector<std::string> yTickLabels = yAxis.tickLabels;
    if (o.copyMs > 0)
        for (std::size_t i = 0; i < yAxis.ticks.size(); ++i)
            yTickLabels[i] += " " + o.yLabel + " = " + formatValue(yAxis.ticks[i] / o.copyMs) + " copies";

    const double text = 2.0, small = 1.5, lineHeight = measureText("0", text).height;
    const int width = 960, height = 600;
    double tickWidth = 0, legendWidth = measureText(o.legend, small).width - 30 - 8;
    for (const std::string& label : yTickLabels)
        tickWidth = std::max(tickWidth, measureText(label, small).width);
    for (const Series& s : series) legendWidth = std::max(legendWidth, measureText(s.name, small).width);
    const double left = 16 + lineHeight + 12 + tickWidth + 8, right = width - 16 - legendWidth - 8 - 30 - 20;
    const double noteHeight = measureText("0", small).height;
    const double top = 60, bottom = height - 16 - noteHeight - 12 - 20 - 2 * lineHeight;
    auto px = [&](double x) { return left + xAxis.fraction(x) * (right - left); };
    auto py = [&](double y) { return bottom - yAxis.fraction(y) * (bottom - top); };
    const Rgba ink = plot_colours::kInk;

    Canvas canvas(width, height, plot_colours::kBackground);
    drawText(canvas, 16, 20, o.title, text, ink);
    for (std::size_t i = 0; i < yAxis.ticks.size(); ++i) {
        const double y = py(yAxis.ticks[i]);
        canvas.drawLine(left, y, right, y, 1, plot_colours::kGrid);
        const TextSize t = measureText(yTickLabels[i], small);
        drawText(canvas, left - 8 - t.width, y - t.height / 2, yTickLabels[i], small, ink);
    }
    for (std::size_t i = 0; i < xTicks.size(); ++i) {
        const double x = px(xTicks[i]);
        canvas.drawLine(x, top, x, bottom, 1, plot_colours::kGrid);
        drawText(canvas, x - measureText(xTickLabels[i], text).width / 2, bottom + 10, xTickLabels[i], text,
                 ink);
    }
    const std::string xLabel = o.xLabel + " (log)", yLabel = o.yLabel + " (log)";
    drawText(canvas, (left + right - measureText(xLabel, text).width) / 2, bottom + 20 + lineHeight, xLabel,
             text, ink);
    drawText(canvas, 16, (top + bottom + measureText(yLabel, text).width) / 2, yLabel, text, ink,
             TextDirection::Upwards);
    canvas.strokeRect(left, top, right, bottom, 1.5, ink);

    double legendY = top + 10;
    if (!o.legend.empty()) {
        drawText(canvas, right + 20, legendY, o.legend, small, ink);
        legendY += 28;
    }
    for (std::size_t i = 0; i < series.size(); ++i) {
        const Rgba colour = kLineColours[i % std::size(kLineColours)];
        const std::vector<SeriesPoint>& p = series[i].points;
        for (std::size_t k = 1; k < p.size(); ++k)
            canvas.drawLine(px(p[k - 1].x), py(p[k - 1].y), px(p[k].x), py(p[k].y), 2.5, colour);
        for (const SeriesPoint& q : p) canvas.fillDisc(px(q.x), py(q.y), 5, colour);
        canvas.drawLine(right + 20, legendY + 5, right + 50, legendY + 5, 3, colour);
        drawText(canvas, right + 58, legendY, series[i].name, small, ink);
        legendY += 28;
    }
    const std::string note = mostRuns <= 1 ? "one run per point"
                             : fewestRuns == mostRuns
                                 ? "median of " + std::to_string(mostRuns) + " runs per point"
                                 : "median of " + std::to_string(fewestRuns) + " to " +
                                       std::to_string(mostRuns) + " runs per point";
    drawText(canvas, 16, height - 16 - noteHeight, note, small, plot_colours::kNote);
    return canvas.toImage();
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    if (!parseArguments(argc, argv, o)) return 2;
    const Result<std::string> text = readTextFile(o.csv);
    if (!text) {
        std::fprintf(stderr, "%s\n", text.error().c_str());
        return 1;
    }
    const Result<std::vector<Series>> series = readSeriesCsv(*text, o.columns, o.csv);
    if (!series) {
        std::fprintf(stderr, "%s\n", series.error().c_str());
        return 1;
    }
    for (const Series& s : *series)
        for (const SeriesPoint& p : s.points)
            if (!(p.x > 0 && p.y > 0)) {
                std::fprintf(stderr, "%s: series '%s' has y = %g at x = %g; log axes need both above 0\n",
                             o.csv.c_str(), s.name.c_str(), p.y, p.x);
                return 1;
            }
    // The medians as text too, for a table beside the picture.
    for (const Series& s : *series)
        for (const SeriesPoint& p : s.points)
            std::printf("%s = %-20s %s = %-10g median %s = %.4g (%d run%s)\n", o.columns.series.c_str(),
                        s.name.c_str(), o.columns.x.c_str(), p.x, o.yLabel.c_str(), p.y, p.runs,
                        p.runs == 1 ? "" : "s");
    if (Status s = writePng(o.png, draw(o, *series)); !s) {
        std::fprintf(stderr, "%s\n", s.error().c_str());
        return 1;
    }
    return 0;
}
