#include "base/series_csv.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <map>

namespace fx {
namespace {

// The whole field as a finite number ("12.5", " 3 ", "1e3"); nothing for "", "12ms", "nan", "inf".
bool parseNumber(const std::string& text, double& value) {
    const char* begin = text.c_str();
    char* end = nullptr;
    errno = 0;
    value = std::strtod(begin, &end);
    if (end == begin || errno == ERANGE) return false;
    while (*end == ' ') ++end;
    return *end == '\0' && std::isfinite(value);
}

}  // namespace

std::vector<std::string> splitCsvLine(std::string_view line) {
    std::vector<std::string> out(1);
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (c == '"' && quoted && i + 1 < line.size() && line[i + 1] == '"')
            out.back() += line[++i];
        else if (c == '"')
            quoted = !quoted;
        else if (c == ',' && !quoted)
            out.emplace_back();
        else
            out.back() += c;
    }
    return out;
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2.0;
}

Result<std::vector<Series>> readSeriesCsv(std::string_view text, const SeriesColumns& columns,
                                          std::string_view source) {
    const std::string where(source);
    std::vector<std::string> lines;
    for (std::size_t start = 0; start < text.size();) {
        std::size_t end = std::min(text.find('\n', start), text.size());
        std::string_view line = text.substr(start, end - start);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);  // a table saved on Windows
        lines.emplace_back(line);
        start = end + 1;
    }
    if (lines.empty() || lines[0].empty()) return Error{where + ": no header line"};
    const std::vector<std::string> header = splitCsvLine(lines[0]);
    auto column = [&](const std::string& name, std::size_t& index) -> Status {
        const auto it = std::find(header.begin(), header.end(), name);
        if (it != header.end()) {
            index = std::size_t(it - header.begin());
            return {};
        }
        std::string known;
        for (const std::string& h : header) known += (known.empty() ? "" : ", ") + h;
        return Error{where + ": no column '" + name + "' in the header (it has " + known + ")"};
    };
    std::size_t xCol = 0, seriesCol = 0;
    std::vector<std::size_t> yCols(columns.y.size());
    if (columns.y.empty()) return Error{where + ": no column named for y"};
    if (Status s = column(columns.x, xCol); !s) return Error{s.error()};
    if (Status s = column(columns.series, seriesCol); !s) return Error{s.error()};
    for (std::size_t i = 0; i < columns.y.size(); ++i)
        if (Status s = column(columns.y[i], yCols[i]); !s) return Error{s.error()};

    std::vector<std::string> order;                                     // names, first seen first
    std::map<std::string, std::map<double, std::vector<double>>> runs;  // name -> x -> y of each run
    for (std::size_t n = 1; n < lines.size(); ++n) {
        if (lines[n].empty()) continue;
        const std::vector<std::string> f = splitCsvLine(lines[n]);
        const std::string at = where + " line " + std::to_string(n + 1);
        if (f.size() < header.size())
            return Error{at + ": " + std::to_string(f.size()) + " fields, the header has " +
                         std::to_string(header.size())};
        auto number = [&](std::size_t col, double& value) -> Status {
            if (parseNumber(f[col], value)) return {};
            return Error{at + ", column " + header[col] + ": '" + f[col] + "' is not a finite number"};
        };
        double x = 0.0, y = 0.0;
        if (Status s = number(xCol, x); !s) return Error{s.error()};
        for (std::size_t col : yCols) {
            double part = 0.0;
            if (Status s = number(col, part); !s) return Error{s.error()};
            y += part;
        }
        const std::string& name = f[seriesCol];
        if (!runs.count(name)) order.push_back(name);
        runs[name][x].push_back(y);
    }
    if (order.empty()) return Error{where + ": no rows below the header"};

    std::vector<Series> out;
    for (const std::string& name : order) {
        Series series{name, {}};
        for (const auto& [x, ys] : runs[name]) series.points.push_back({x, median(ys), int(ys.size())});
        out.push_back(std::move(series));
    }
    return out;
}

}  // namespace fx
