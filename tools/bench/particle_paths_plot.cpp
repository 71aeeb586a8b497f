// Lesson 07's bench as a picture: frame time against particle count for the three simulation paths
// (one draw per particle, one instanced draw, GPU simulation with an indirect draw), both axes
// logarithmic, from the `workload` rows of the bench.csv that `./fxlab bench 07` writes. The y axis
// also reads in full-screen copies of the same run.
//   fx_particle_paths_plot out/bench/07-fire-emitter/bench.csv docs/images/bench-07-paths.png
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "image/canvas.hpp"
#include "image/canvas_text.hpp"
#include "image/png_file.hpp"

namespace {

using namespace fx;

// One CSV line's fields; quoted fields may hold commas.
std::vector<std::string> fields(const std::string& line) {
    std::vector<std::string> out(1);
    bool quoted = false;
    for (char c : line) {
        if (c == '"')
            quoted = !quoted;
        else if (c == ',' && !quoted)
            out.emplace_back();
        else
            out.back() += c;
    }
    return out;
}

struct Path {
    const char* name;
    const char* label;
    Rgba colour;
};
const Path kPaths[] = {{"objects", "one draw per particle", {204, 0, 0, 255}},
                       {"instanced", "one instanced draw", {52, 101, 164, 255}},
                       {"gpu", "GPU sim, indirect draw", {245, 121, 0, 255}}};

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: %s BENCH_CSV OUTPUT_PNG\n", argv[0]);
        return 2;
    }
    std::ifstream in(argv[1]);
    std::string line;
    if (!in || !std::getline(in, line)) {
        std::fprintf(stderr, "%s: cannot read the bench table\n", argv[1]);
        return 1;
    }
    const std::vector<std::string> header = fields(line);
    auto column = [&](const char* name) {
        return std::size_t(std::find(header.begin(), header.end(), name) - header.begin());
    };
    const std::size_t knobCol = column("knob"), valueCol = column("value"), msCol = column("median_ms"),
                      copyCol = column("copy_ms"), widthCol = column("width"), heightCol = column("height");
    std::map<std::string, std::vector<std::pair<double, double>>> series;  // path -> (count, ms)
    double copyMs = 0;
    std::string size;
    while (std::getline(in, line)) {
        std::vector<std::string> f = fields(line);
        if (f.size() < header.size() || f[knobCol] != "workload") continue;
        const std::string& value = f[valueCol];
        std::size_t space = value.find(' ');
        if (space == std::string::npos) continue;  // "params": the lesson's own setting
        series[value.substr(0, space)].emplace_back(std::stod(value.substr(space + 1)), std::stod(f[msCol]));
        copyMs = std::stod(f[copyCol]);
        size = f[widthCol] + "x" + f[heightCol];
    }
    double minCount = 1e30, maxCount = 0, minMs = 1e30, maxMs = 0;
    for (auto& [name, points] : series)
        for (auto [count, ms] : points) {
            minCount = std::min(minCount, count), maxCount = std::max(maxCount, count);
            minMs = std::min(minMs, ms), maxMs = std::max(maxMs, ms);
        }
    if (maxCount <= 0 || minMs <= 0) {
        std::fprintf(stderr, "%s: no workload rows (run ./fxlab bench 07 --knob workload)\n", argv[1]);
        return 1;
    }

    const int width = 960, height = 600;
    const double left = 190, right = 660, top = 60, bottom = 520;
    const double x0 = std::floor(std::log10(minCount)),
                 x1 = std::max(std::ceil(std::log10(maxCount)), x0 + 1);
    const double y0 = std::floor(std::log10(minMs)), y1 = std::max(std::ceil(std::log10(maxMs)), y0 + 1);
    auto px = [&](double count) { return left + (std::log10(count) - x0) / (x1 - x0) * (right - left); };
    auto py = [&](double ms) { return bottom - (std::log10(ms) - y0) / (y1 - y0) * (bottom - top); };
    const Rgba ink{40, 40, 40, 255}, grid{226, 226, 226, 255};

    Canvas canvas(width, height, {255, 255, 255, 255});
    drawText(canvas, left, 20, "Lesson 07 at " + size + ": frame time against particles (log-log, one run)",
             2, ink);
    for (double e = y0; e <= y1; ++e)
        for (double m : {1.0, 2.0, 5.0}) {
            double ms = m * std::pow(10.0, e);
            if (ms > std::pow(10.0, y1) * 1.001) continue;
            canvas.drawLine(left, py(ms), right, py(ms), 1, grid);
            char text[64];
            std::snprintf(text, sizeof text, "%g ms = %.0f copies", ms, copyMs > 0 ? ms / copyMs : 0.0);
            TextSize t = measureText(text, 1.5);
            drawText(canvas, left - 8 - t.width, py(ms) - t.height / 2, text, 1.5, ink);
        }
    for (double e = x0; e <= x1; ++e) {
        double count = std::pow(10.0, e);
        canvas.drawLine(px(count), top, px(count), bottom, 1, grid);
        std::string text = std::to_string(long(count));
        drawText(canvas, px(count) - measureText(text, 2).width / 2, bottom + 10, text, 2, ink);
    }
    drawText(canvas, (left + right) / 2 - 70, bottom + 40, "particles alive", 2, ink);
    canvas.strokeRect(left, top, right, bottom, 1.5, ink);
    double legendY = top + 10;
    for (const Path& p : kPaths) {
        auto it = series.find(p.name);
        if (it != series.end()) {
            std::vector<std::pair<double, double>> points = it->second;
            std::sort(points.begin(), points.end());
            for (std::size_t i = 1; i < points.size(); ++i)
                canvas.drawLine(px(points[i - 1].first), py(points[i - 1].second), px(points[i].first),
                                py(points[i].second), 2.5, p.colour);
            for (auto [count, ms] : points) canvas.fillDisc(px(count), py(ms), 5, p.colour);
        }
        canvas.drawLine(right + 20, legendY + 7, right + 50, legendY + 7, 3, p.colour);
        drawText(canvas, right + 58, legendY + 1, p.label, 1.5, ink);
        legendY += 28;
    }
    if (Status s = writePng(argv[2], canvas.toImage()); !s) {
        std::fprintf(stderr, "%s\n", s.error().c_str());
        return 1;
    }
    return 0;
}
