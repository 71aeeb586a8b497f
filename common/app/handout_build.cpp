#include "app/handout_build.hpp"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <map>
#include <set>

#include <unistd.h>

#include "app/capture.hpp"
#include "app/handout_words.hpp"
#include "app/lesson_listing.hpp"
#include "app/lesson_switch.hpp"
#include "app/lesson_text_files.hpp"
#include "base/file_io.hpp"
#include "base/lesson_text.hpp"
#include "base/log.hpp"
#include "base/paths.hpp"
#include "render/graph_dot.hpp"

namespace fx::handout {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

// A member of a JSON object, or null: never a copy, so a reference into a report stays valid.
const json& member(const json& object, const char* key) {
    static const json none;
    if (!object.is_object()) return none;
    auto it = object.find(key);
    return it == object.end() ? none : *it;
}

// "WxH" from a report's [w, h], or "?".
std::string sizeText(const json& size) {
    if (!size.is_array() || size.size() != 2 || !size[0].is_number() || !size[1].is_number()) return "?";
    return cat(size[0].get<int>(), "x", size[1].get<int>());
}

// "fxlab-06-bloom" -> {6, "bloom"}.
Result<LessonInfo> lessonOf(const fs::path& executable) {
    const std::string name = executable.filename().string();
    const bool shaped = name.size() > 9 && name.rfind("fxlab-", 0) == 0 &&
                        std::isdigit(static_cast<unsigned char>(name[6])) &&
                        std::isdigit(static_cast<unsigned char>(name[7])) && name[8] == '-';
    if (!shaped) return Error{cat(executable.string(), ": not a lesson executable (fxlab-NN-name)")};
    LessonInfo info;
    info.number = (name[6] - '0') * 10 + (name[7] - '0');
    info.slug = name.substr(9);
    return info;
}

// The last lines of a log, for an error message.
std::string logTail(const fs::path& log, int lines = 12) {
    auto text = readTextFile(log);
    if (!text) return "(no log)";
    std::string s = *text;
    while (!s.empty() && s.back() == '\n') s.pop_back();
    std::size_t start = s.size();
    for (int n = 0; n < lines && start > 0; ++n) {
        start = s.rfind('\n', start - 1);
        if (start == std::string::npos) {
            start = 0;
            break;
        }
    }
    return s.substr(start == 0 ? 0 : start + 1);
}

Result<json> readJson(const fs::path& file) {
    auto text = readTextFile(file);
    if (!text) return Error{text.error()};
    json j = json::parse(*text, nullptr, false);
    if (j.is_discarded()) return Error{cat(file.string(), ": not valid JSON")};
    return j;
}

// Runs a program with its output in `log`; an error quotes the log's end.
Status run(const fs::path& program, const std::vector<std::string>& args, const fs::path& log,
           const std::string& what) {
    auto code = runAndWait(program, args, log);
    if (!code) return Error{cat(what, ": ", code.error())};
    if (*code != 0)
        return Error{cat(what, " failed (exit code ", *code, "); the end of its output:\n", logTail(log))};
    return Status::success();
}

Status moveFile(const fs::path& from, const fs::path& to) {
    std::error_code ec;
    fs::rename(from, to, ec);
    if (ec) return Error{cat(from.string(), " -> ", to.string(), ": ", ec.message())};
    return Status::success();
}

Status copyFile(const fs::path& from, const fs::path& to) {
    auto bytes = readFile(from, file_limits::png);
    if (!bytes) return Error{bytes.error()};
    return writeFileAtomically(to, *bytes);
}

// One captured step: its folder and its report.
struct CapturedStep {
    fs::path folder;
    json report;
    std::string dot;
};

// "bloom.down[1]  160x90  RGBA16F"; a level of a chain says only "[1] 160x90", its strip the rest.
std::string textureCaption(const json& texture, bool inChain) {
    const std::string name = texture.value("name", std::string());
    const std::string size = sizeText(member(texture, "size"));
    if (inChain) return cat(name.substr(name.find('[')), " ", size);
    return cat(name, "  ", size, "  ", texture.value("format", std::string()));
}

// The textures a step's text points at (`bloom.down[0]`) that the step's frame made; a name with an
// index shows its whole chain, as the inspector's strip does.
std::vector<View> viewsOf(const CapturedStep& step, const std::string& englishText, int number,
                          const fs::path& folder, Status& status) {
    std::map<std::string, const json*> captured;
    for (const json& t : member(step.report, "textures")) {
        const std::string name = t.value("name", std::string());
        std::error_code ec;
        if (fs::is_regular_file(step.folder / (captureFileStem(name) + ".png"), ec)) captured[name] = &t;
    }
    std::vector<View> views;
    std::set<std::string> shown;
    auto picture = [&](const std::string& name, bool inChain) -> Picture {
        const std::string file = cat("step-", number, "-", captureFileStem(name), ".png");
        if (status) status = moveFile(step.folder / (captureFileStem(name) + ".png"), folder / file);
        shown.insert(name);
        const json& t = *captured.at(name);
        const json& size = member(t, "size");
        const bool sized = size.is_array() && size.size() == 2;
        return {file, textureCaption(t, inChain), sized ? size[0].get<int>() : 0,
                sized ? size[1].get<int>() : 0};
    };
    for (const std::string& name : codeSpans(englishText)) {
        if (!captured.contains(name) || shown.contains(name)) continue;
        const std::size_t bracket = name.find('[');
        if (bracket != std::string::npos && name.back() == ']') {
            const std::string base = name.substr(0, bracket);
            View chain;
            for (int k = 0; captured.contains(cat(base, "[", k, "]")); ++k) {
                if (!shown.contains(cat(base, "[", k, "]")))
                    chain.pictures.push_back(picture(cat(base, "[", k, "]"), true));
            }
            chain.title = cat(base, "[0 .. ", chain.pictures.size() - 1, "]  ",
                              captured.at(name)->value("format", std::string()));
            if (!chain.pictures.empty()) views.push_back(std::move(chain));
        } else {
            views.push_back({name, {picture(name, false)}});
        }
    }
    return views;
}

// The pictures a lesson's texts show, copied into figures/: target -> file in the handout.
class TextPictures {
public:
    TextPictures(fs::path lessonFolder, fs::path handout)
        : lesson_(std::move(lessonFolder)), handout_(std::move(handout)) {}

    Status add(const std::string& markdown, const fs::path& source) {
        for (const std::string& target : pictureTargets(markdown)) {
            if (files_.contains(target)) continue;
            const fs::path from = (lesson_ / target).lexically_normal();
            std::error_code ec;
            if (target.find("://") != std::string::npos || !fs::is_regular_file(from, ec))
                return Error{cat(source.string(), ": the picture \"", target,
                                 "\" is not a file of the lesson (", from.string(), ")")};
            std::string name = from.filename().string();
            for (int n = 2; used_.contains(name); ++n) name = cat(n, "-", from.filename().string());
            used_.insert(name);
            if (auto s = copyFile(from, handout_ / "figures" / name); !s) return s;
            files_[target] = "figures/" + name;
        }
        return Status::success();
    }
    PictureSource source() const {
        return [this](const std::string& target) {
            auto it = files_.find(target);
            return it == files_.end() ? target : it->second;
        };
    }

private:
    fs::path lesson_, handout_;
    std::map<std::string, std::string> files_;
    std::set<std::string> used_;
};

// A frame graph drawn as SVG, in the direction that fits the printed page better.
struct DrawnGraph {
    fs::path file;
    int width = 0, height = 0;  // CSS pixels
};

// The <svg width="567pt" height="1860pt"> dot writes, in CSS pixels (96 per inch).
std::pair<double, double> svgSize(const std::string& svg) {
    auto attribute = [&](const std::string& key) {
        const std::size_t at = svg.find(key + "=\"");
        return at == std::string::npos ? 0.0 : std::atof(svg.c_str() + at + key.size() + 2) * 96.0 / 72.0;
    };
    return {attribute("width"), attribute("height")};
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
        if (auto s =
                run(dot, {"-Tsvg", "-Granksep=0.22", "-Gnodesep=0.15", "-o", svg.string(), source.string()},
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

// lesson.md (or a translation) split into title, intro and the parts that are not steps.
struct LessonText {
    std::string title, intro;
    std::vector<Part> before, after;
};

Result<LessonText> readLessonText(const fs::path& file, bool englishOnly) {
    auto text = readTextFile(file);
    if (!text) return Error{text.error()};
    LessonText out;
    bool stepsBegan = false;
    for (const LessonSection& s : parseLessonSections(*text)) {
        if (s.level <= 1) {
            if (s.level == 1 && out.title.empty()) out.title = s.heading;
            out.intro += (out.intro.empty() ? "" : "\n\n") + s.text;
        } else if (isStepSection(s)) {
            stepsBegan = true;
        } else {
            (stepsBegan ? out.after : out.before).push_back({s.heading, s.text, englishOnly});
        }
    }
    if (out.title.empty()) return Error{cat(file.string(), ": no \"# \" heading (the lesson's title)")};
    return out;
}

std::string madeWith(const std::string& language, const json& report, int frames) {
    const Words& w = wordsFor(language);
    const std::string pixels = sizeText(member(report, "size"));
    const std::string renderer = report.value("renderer", std::string("?"));
    if (language == "ja")
        return cat(pixels, "、", frames, " フレーム目", w.frameOf, "、", w.renderedBy, renderer);
    return cat(pixels, ", frame ", frames, w.frameOf, ", ", w.renderedBy, renderer);
}

// The bench's results for the lesson, if there are any.
Result<BenchPart> readBench(const fs::path& benchFolder, const fs::path& folder) {
    BenchPart bench;
    bench.applicable = true;
    std::error_code ec;
    if (!fs::is_regular_file(benchFolder / "bench.json", ec)) return bench;
    auto j = readJson(benchFolder / "bench.json");
    if (!j) return Error{j.error()};
    bench.found = true;
    const double copyMs = j->value("copyMs", 0.0);
    bench.size = sizeText(member(*j, "size"));
    bench.timing = j->value("timingMethod", std::string());
    bench.copyMs = copyMs;
    std::vector<std::string> knobs;
    for (const json& p : member(*j, "points")) {
        const std::string knob = p.value("knob", std::string());
        if (std::find(knobs.begin(), knobs.end(), knob) == knobs.end()) knobs.push_back(knob);
        const json& rmse = p.value("rmse", json());
        bench.rows.push_back({knob, p.value("value", std::string()), p.value("reference", false),
                              p.value("current", false),
                              copyMs > 0 ? p.value("copyMultiple", 0.0) : p.value("medianMs", 0.0),
                              rmse.is_number() ? rmse.get<double>() : 0.0});
    }
    for (const std::string& knob : knobs) {
        const std::string file = cat("bench-", knob, ".png");
        if (!fs::is_regular_file(benchFolder / file, ec)) continue;
        if (!fs::exists(folder / file, ec)) {
            if (auto s = copyFile(benchFolder / file, folder / file); !s) return Error{s.error()};
        }
        bench.plots.push_back({file, knob, 0, 0});
    }
    return bench;
}

}  // namespace

Result<std::string> lessonFolderOf(const fs::path& executable) {
    auto info = lessonOf(executable);
    if (!info) return Error{info.error()};
    return lessonFolderName(*info);
}

fs::path findProgram(const std::string& name) {
    const char* path = std::getenv("PATH");
    std::string dirs = path ? path : "/usr/bin:/bin";
    std::size_t start = 0;
    while (start <= dirs.size()) {
        std::size_t end = dirs.find(':', start);
        if (end == std::string::npos) end = dirs.size();
        const fs::path candidate = fs::path(dirs.substr(start, end - start)) / name;
        if (end > start && ::access(candidate.c_str(), X_OK) == 0) return candidate;
        start = end + 1;
    }
    return {};
}

Status writeStyle(const fs::path& folder) {
    const fs::path css = resourceDir() / "handout" / "style.css";
    auto text = readTextFile(css);
    if (!text) return Error{text.error()};
    return writeFileAtomically(folder / "style.css", *text);
}

Status writeContents(const std::vector<ContentsEntry>& lessons, const std::vector<std::string>& languages,
                     const fs::path& folder) {
    std::vector<std::pair<std::string, std::string>> pages;
    for (const std::string& l : languages) pages.emplace_back(l, pageFileFor(l, languages));
    for (const std::string& l : languages) {
        const std::string file = pageFileFor(l, languages);
        if (auto s = writeFileAtomically(folder / file, contentsPageHtml(lessons, l, pages, file)); !s)
            return s;
    }
    return writeStyle(folder);
}

namespace {

Result<ContentsEntry> buildLesson(const fs::path& executable, const HandoutOptions& options,
                                  const fs::path& folder) {
    auto info = lessonOf(executable);
    if (!info) return Error{info.error()};
    const std::string name = lessonFolderName(*info);  // "06-bloom"
    const fs::path lessonFolder = lessonSourceFolder(*info);
    const fs::path work = folder / ".work";
    std::error_code ec;
    fs::create_directories(work, ec);
    if (ec) return Error{cat(work.string(), ": ", ec.message())};

    const fs::path dot = findProgram("dot");
    if (dot.empty())
        return Error{
            "Graphviz's dot is not on PATH: it draws the frame graphs (Debian: apt-get install graphviz; "
            "./fxlab handout installs it)"};

    // Every step, captured by the lesson itself at a fixed moment of its headless clock.
    const auto started = std::chrono::steady_clock::now();
    options.progress(cat(name, ": capturing every step at ", toString(options.size), " (", options.frames,
                         " frames each)"));
    if (auto s = run(executable,
                     {"--all-steps", "--headless", "--size", toString(options.size), "--frames",
                      std::to_string(options.frames), "--capture", (work / "captures").string()},
                     work / "capture.log", cat(name, ": capturing the steps"));
        !s)
        return Error{s.error()};
    std::vector<CapturedStep> captured;
    for (int k = 1;; ++k) {
        const fs::path stepFolder = work / "captures" / cat("step-", k);
        if (!fs::exists(stepFolder / "report.json", ec)) break;
        auto report = readJson(stepFolder / "report.json");
        if (!report) return Error{report.error()};
        auto graph = readTextFile(stepFolder / "graph.dot");
        if (!graph) return Error{graph.error()};
        captured.push_back({stepFolder, std::move(*report), std::move(*graph)});
    }
    if (captured.empty())
        return Error{cat(name, ": the capture wrote no step (", (work / "captures").string(), ")")};
    std::vector<std::string> titles;
    for (const CapturedStep& c : captured) titles.push_back(c.report.value("stepTitle", std::string()));

    // The lesson's text in every language, read as the overlay reads it.
    auto english = readLessonText(lessonFolder / "lesson.md", false);
    if (!english) return Error{english.error()};
    LessonTextFiles englishSteps(lessonFolder, titles, "en");
    (void)englishSteps.reloadIfChanged();
    if (!englishSteps.error().empty()) return Error{englishSteps.error()};
    TextPictures textPictures(lessonFolder, folder);

    // What every page shares: the step's picture, views, facts and frame.
    std::vector<StepPage> steps;
    std::map<std::string, int> graphs;  // dot text -> the step that showed it first
    for (std::size_t i = 0; i < captured.size(); ++i) {
        const CapturedStep& c = captured[i];
        const int number = int(i) + 1;
        StepPage step;
        step.number = number;
        const std::string picture = cat("step-", number, ".png");
        if (auto s = moveFile(c.folder / "final.png", folder / picture); !s)
            return Error{cat(name, ": step ", number, " has no picture: ", s.error())};
        step.picture = {picture, {}, options.size.width, options.size.height};
        for (const json& f : member(c.report, "shownFacts"))
            step.facts.emplace_back(f.value("label", std::string()), f.value("value", std::string()));
        Status moved;
        step.views = viewsOf(c, englishSteps.steps()[i].text, number, folder, moved);
        if (!moved) return Error{cat(name, ": step ", number, ": ", moved.error())};
        if (auto seen = graphs.find(c.dot); seen != graphs.end()) {
            step.sameFrameAs = seen->second;
        } else {
            graphs[c.dot] = number;
            auto graph = drawGraph(dot, c.dot, work, cat(name, ": step ", number));
            if (!graph) return Error{graph.error()};
            step.graphFile = cat("step-", number, "-graph.svg");
            if (auto s = moveFile(graph->file, folder / step.graphFile); !s) return Error{s.error()};
            step.graphWidth = graph->width;
            step.graphHeight = graph->height;
            step.passes = member(c.report, "passes");
        }
        steps.push_back(std::move(step));
    }

    // The bench, for a lesson with quality knobs: earlier results, or a run now.
    fs::path benchFolder = options.benchRoot / name;
    if (auto s = run(executable, {"--list-params"}, work / "params.log", cat(name, ": --list-params")); !s)
        return Error{s.error()};
    auto params = readTextFile(work / "params.log");
    const bool hasKnobs = params && params->find("quality knob") != std::string::npos;
    if (options.withBench && hasKnobs) {
        options.progress(cat(name, ": running the bench"));
        benchFolder = work / "bench";
        auto code =
            runAndWait(executable, {"--bench", "--bench-out", benchFolder.string()}, work / "bench.log");
        if (!code) return Error{cat(name, ": the bench: ", code.error())};
        auto log = readTextFile(work / "bench.log");
        const bool noKnobs = log && log->find("has no quality knobs") != std::string::npos;
        if (*code != 0 && !noKnobs)
            return Error{cat(name, ": the bench failed (exit code ", *code, "); the end of its output:\n",
                             logTail(work / "bench.log"))};
    }

    BenchPart bench;
    if (hasKnobs) {
        auto found = readBench(benchFolder, folder);
        if (!found) return Error{cat(name, ": ", found.error())};
        bench = *found;
    }

    ContentsEntry entry{name, {}, int(captured.size())};
    std::vector<std::pair<std::string, std::string>> pages;
    for (const std::string& l : options.languages) pages.emplace_back(l, pageFileFor(l, options.languages));
    for (const std::string& language : options.languages) {
        LessonPage page;
        page.language = language;
        page.languages = pages;
        LessonText own = *english;
        if (language != "en") {
            auto translated = readLessonText(lessonFolder / ("lesson." + language + ".md"), false);
            if (!translated) return Error{translated.error()};
            own.title = translated->title;
            own.intro = translated->intro;
            page.englishIntro = english->intro;
            for (Part& p : own.before) p.englishOnly = true;
            for (Part& p : own.after) p.englishOnly = true;
            own.before.insert(own.before.end(), translated->before.begin(), translated->before.end());
            own.after.insert(own.after.end(), translated->after.begin(), translated->after.end());
        }
        page.title = own.title;
        page.intro = own.intro;
        page.before = own.before;
        page.after = own.after;
        page.madeWith = madeWith(language, captured.front().report, options.frames);
        LessonTextFiles text(lessonFolder, titles, language);
        (void)text.reloadIfChanged();
        if (!text.error().empty()) return Error{text.error()};
        page.steps = steps;
        for (std::size_t i = 0; i < steps.size(); ++i) {
            page.steps[i].title = text.steps()[i].title;
            page.steps[i].text = text.steps()[i].text;
            page.steps[i].note = text.steps()[i].note;
            page.steps[i].picture.caption =
                cat(wordsFor(language).step, " ", i + 1, ": ", page.steps[i].title);
        }
        const fs::path source =
            lessonFolder / (language == "en" ? "lesson.md" : "lesson." + language + ".md");
        for (const std::string* markdown : {&page.intro, &page.englishIntro})
            if (auto s = textPictures.add(*markdown, source); !s) return Error{s.error()};
        for (const auto* parts : {&page.before, &page.after})
            for (const Part& p : *parts)
                if (auto s = textPictures.add(p.text, source); !s) return Error{s.error()};
        for (const StepPage& s : page.steps)
            if (auto added = textPictures.add(s.text, source); !added) return Error{added.error()};
        page.bench = bench;
        entry.titles[language] = page.title;
        const std::string html = lessonPageHtml(page, textPictures.source());
        if (auto s = writeFileAtomically(folder / pageFileFor(language, options.languages), html); !s)
            return Error{s.error()};
    }
    if (auto s = writeStyle(folder); !s) return Error{s.error()};
    fs::remove_all(work, ec);
    if (ec) return Error{cat(work.string(), ": ", ec.message())};
    const auto seconds =
        std::chrono::duration_cast<std::chrono::seconds>(std::chrono::steady_clock::now() - started).count();
    options.progress(cat(name, ": ", captured.size(), " steps written in ", seconds, " s"));
    return entry;
}

}  // namespace

Result<ContentsEntry> writeLessonHandout(const fs::path& executable, const HandoutOptions& options,
                                         const fs::path& folder) {
    try {
        return buildLesson(executable, options, folder);
    } catch (const nlohmann::json::exception& e) {
        // A report or bench.json of another shape than the one this reads: say so, do not crash.
        return Error{
            cat(executable.filename().string(), ": a report is not what the handout reads: ", e.what())};
    }
}

}  // namespace fx::handout
