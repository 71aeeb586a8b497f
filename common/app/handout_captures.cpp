#include "app/handout_captures.hpp"

#include <algorithm>
#include <cstdlib>
#include <map>
#include <set>

#include "app/capture.hpp"
#include "base/file_io.hpp"
#include "base/log.hpp"
#include "render/graph_dot.hpp"

namespace fx::handout {
namespace {

namespace fs = std::filesystem;

// "bloom.down[1]  160x90  RGBA16F"; a level of a chain says only "[1] 160x90", its strip the rest.
std::string textureCaption(const json& texture, bool inChain) {
    const std::string name = texture.value("name", std::string());
    const std::string size = sizeText(member(texture, "size"));
    if (inChain) return cat(name.substr(name.find('[')), " ", size);
    return cat(name, "  ", size, "  ", texture.value("format", std::string()));
}

// The <svg width="567pt" height="1860pt"> dot writes, in CSS pixels (96 per inch).
std::pair<double, double> svgSize(const std::string& svg) {
    auto attribute = [&](const std::string& key) {
        const std::size_t at = svg.find(key + "=\"");
        return at == std::string::npos ? 0.0 : std::atof(svg.c_str() + at + key.size() + 2) * 96.0 / 72.0;
    };
    return {attribute("width"), attribute("height")};
}

}  // namespace

Result<std::vector<CapturedStep>> readCapturedSteps(const fs::path& dir) {
    std::vector<CapturedStep> steps;
    std::error_code ec;
    for (int k = 1;; ++k) {
        const fs::path folder = dir / cat("step-", k);
        if (!fs::exists(folder / "report.json", ec)) break;
        auto report = readJson(folder / "report.json");
        if (!report) return Error{report.error()};
        auto graph = readTextFile(folder / "graph.dot");
        if (!graph) return Error{graph.error()};
        steps.push_back({folder, std::move(*report), std::move(*graph)});
    }
    return steps;
}

Result<std::vector<View>> takeViews(const CapturedStep& step, const std::string& text, int number,
                                    const fs::path& folder) {
    std::map<std::string, const json*> captured;  // texture name -> its entry in the report
    for (const json& t : member(step.report, "textures")) {
        const std::string name = t.value("name", std::string());
        std::error_code ec;
        if (fs::is_regular_file(step.folder / (captureFileStem(name) + ".png"), ec)) captured[name] = &t;
    }
    std::vector<View> views;
    std::set<std::string> shown;
    Status moved;
    auto picture = [&](const std::string& name, bool inChain) -> Picture {
        const std::string file = cat("step-", number, "-", captureFileStem(name), ".png");
        if (moved) moved = moveFile(step.folder / (captureFileStem(name) + ".png"), folder / file);
        shown.insert(name);
        const json& t = *captured.at(name);
        const json& size = member(t, "size");
        const bool sized = size.is_array() && size.size() == 2;
        return {file, textureCaption(t, inChain), sized ? size[0].get<int>() : 0,
                sized ? size[1].get<int>() : 0};
    };
    for (const std::string& name : codeSpans(text)) {
        if (!captured.contains(name) || shown.contains(name)) continue;
        const std::size_t bracket = name.find('[');
        if (bracket == std::string::npos || name.back() != ']') {
            views.push_back({name, {picture(name, false)}});
            continue;
        }
        const std::string base = name.substr(0, bracket);
        View chain;
        for (int k = 0; captured.contains(cat(base, "[", k, "]")); ++k) {
            if (!shown.contains(cat(base, "[", k, "]")))
                chain.pictures.push_back(picture(cat(base, "[", k, "]"), true));
        }
        chain.title = cat(base, "[0 .. ", chain.pictures.size() - 1, "]  ",
                          captured.at(name)->value("format", std::string()));
        if (!chain.pictures.empty()) views.push_back(std::move(chain));
    }
    if (!moved) return Error{moved.error()};
    return views;
}

Result<DrawnGraph> drawGraph(const fs::path& dot, const std::string& graph, const fs::path& work,
                             const std::string& what) {
    // A4 less the stylesheet's margins, in CSS pixels: how much of its size a graph keeps on paper.
    const auto fit = [](std::pair<double, double> size) {
        return size.first <= 0 || size.second <= 0 ? 0.0
                                                   : std::min({1.0, 688.0 / size.first, 900.0 / size.second});
    };
    DrawnGraph best;
    double bestFit = -1;
    for (const auto& [suffix, text] :
         {std::pair<std::string, std::string>{"lr", graph}, {"tb", topToBottom(graph)}}) {
        const fs::path source = work / cat("graph-", suffix, ".dot"),
                       svg = work / cat("graph-", suffix, ".svg");
        if (auto s = writeFileAtomically(source, text); !s) return Error{s.error()};
        // Closer ranks and nodes than dot's defaults: a long chain keeps more of its size on a page.
        if (auto s = runLogged(
                dot, {"-Tsvg", "-Granksep=0.22", "-Gnodesep=0.15", "-o", svg.string(), source.string()},
                work / "dot.log", cat(what, ": dot"));
            !s)
            return Error{s.error()};
        auto drawn = readTextFile(svg);
        if (!drawn) return Error{drawn.error()};
        const auto size = svgSize(*drawn);
        if (fit(size) > bestFit) {
            bestFit = fit(size);
            best = {svg, int(size.first + 0.5), int(size.second + 0.5)};
        }
    }
    return best;
}

}  // namespace fx::handout
