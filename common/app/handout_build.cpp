#include "app/handout_build.hpp"

#include <algorithm>
#include <chrono>
#include <map>

#include "app/handout_captures.hpp"
#include "app/handout_io.hpp"
#include "app/handout_sources.hpp"
#include "app/handout_words.hpp"
#include "app/lesson_listing.hpp"
#include "app/lesson_switch.hpp"
#include "app/lesson_text_files.hpp"
#include "base/fact_references.hpp"
#include "base/file_io.hpp"
#include "base/log.hpp"
#include "base/paths.hpp"

namespace fx::handout {
namespace {

namespace fs = std::filesystem;

// "fxlab-06-bloom" -> {6, "bloom"}.
Result<LessonInfo> lessonOf(const fs::path& executable) {
    const std::string name = executable.filename().string();
    if (!isLessonExecutableName(name))
        return Error{cat(executable.string(), ": not a lesson executable (fxlab-NN-name)")};
    LessonInfo info;
    info.number = (name[6] - '0') * 10 + (name[7] - '0');
    info.slug = name.substr(9);
    return info;
}

std::string madeWith(const std::string& language, const json& report, int frames) {
    const Words& w = wordsFor(language);
    const std::string pixels = sizeText(member(report, "size"));
    const std::string renderer = report.value("renderer", std::string("?"));
    if (language == "ja")
        return cat(pixels, "、", frames, " フレーム目", w.frameOf, "、", w.renderedBy, renderer);
    return cat(pixels, ", frame ", frames, w.frameOf, ", ", w.renderedBy, renderer);
}

// Whether the lesson has quality knobs for the bench to sweep: its --list-params says so
// (app/lesson_listing.cpp marks each knob "quality knob").
Result<bool> hasQualityKnobs(const fs::path& executable, const fs::path& work, const std::string& name) {
    if (auto s = runLogged(executable, {"--list-params"}, work / "params.log", cat(name, ": --list-params"));
        !s)
        return Error{s.error()};
    auto params = readTextFile(work / "params.log");
    return params && params->find("quality knob") != std::string::npos;
}

// What every language's page shares: each step's picture, facts, views and frame.
Result<std::vector<StepPage>> stepPages(const std::vector<CapturedStep>& captured,
                                        const std::vector<LessonStep>& english, const HandoutOptions& options,
                                        const fs::path& dot, const fs::path& work, const fs::path& folder,
                                        const std::string& name) {
    std::vector<StepPage> steps;
    std::map<std::string, int> graphs;  // dot text -> the step that showed it first
    for (std::size_t i = 0; i < captured.size(); ++i) {
        const CapturedStep& c = captured[i];
        StepPage step;
        step.number = int(i) + 1;
        const std::string what = cat(name, ": step ", step.number);
        step.picture = {cat("step-", step.number, ".png"), {}, options.size.width, options.size.height};
        if (auto s = moveFile(c.folder / "final.png", folder / step.picture.file); !s)
            return Error{cat(what, " has no picture: ", s.error())};
        for (const json& f : member(c.report, "shownFacts"))
            step.facts.emplace_back(f.value("label", std::string()), f.value("value", std::string()));
        for (const auto& [key, value] : member(c.report, "facts").items())
            step.factValues[key] = value.is_string() ? value.get<std::string>() : value.dump();
        // The English text chooses the views, so every language shows the same textures.
        auto views = takeViews(c, english[i].text, step.number, folder);
        if (!views) return Error{cat(what, ": ", views.error())};
        step.views = std::move(*views);
        if (auto seen = graphs.find(c.dot); seen != graphs.end()) {
            step.sameFrameAs = seen->second;
        } else {
            graphs[c.dot] = step.number;
            auto graph = drawGraph(dot, c.dot, work, what);
            if (!graph) return Error{graph.error()};
            step.graphFile = cat("step-", step.number, "-graph.svg");
            if (auto s = moveFile(graph->file, folder / step.graphFile); !s) return Error{s.error()};
            step.graphWidth = graph->width;
            step.graphHeight = graph->height;
            step.passes = member(c.report, "passes");
        }
        steps.push_back(std::move(step));
    }
    return steps;
}

// The page of one language: its lesson text (English where a part has no translation), the steps as
// the overlay shows them in that language, the shared pictures, and the pictures its texts show.
Result<LessonPage> lessonPage(const std::string& language, const LessonText& english,
                              const fs::path& lessonFolder, const std::vector<std::string>& titles,
                              const std::vector<StepPage>& steps, TextPictures& textPictures) {
    LessonPage page;
    page.language = language;
    const fs::path englishFile = lessonFolder / "lesson.md";
    const fs::path ownFile = language == "en" ? englishFile : lessonFolder / ("lesson." + language + ".md");
    LessonText own = english;
    fs::path introFile = englishFile;
    if (language != "en") {
        for (Part& p : own.before) p.englishOnly = true;
        for (Part& p : own.after) p.englishOnly = true;
        std::error_code ec;
        if (fs::exists(ownFile, ec)) {  // without one, every step shows its English text with a note
            auto translated = readLessonText(ownFile);
            if (!translated) return Error{translated.error()};
            own.title = translated->title;
            own.intro = translated->intro;
            introFile = ownFile;
            page.englishIntro = english.intro;
            // A translated part takes its English part's place; the others stay, marked English only.
            for (auto [mine, theirs] :
                 {std::pair{&own.before, &translated->before}, {&own.after, &translated->after}})
                for (const Part& p : *theirs) replaceOrAdd(*mine, p);
        }
    }
    page.title = own.title;
    page.intro = own.intro;
    page.before = own.before;
    page.after = own.after;

    LessonTextFiles text(lessonFolder, titles, language);
    (void)text.reloadIfChanged();
    if (!text.error().empty()) return Error{text.error()};
    page.steps = steps;
    for (std::size_t i = 0; i < steps.size(); ++i) {
        StepPage& step = page.steps[i];
        step.title = text.steps()[i].title;
        // The numbers the text quotes from its step's facts, as this run computed them.
        step.text = resolveFactReferences(text.steps()[i].text, [&step](const std::string& fact) {
            auto it = step.factValues.find(fact);
            return it == step.factValues.end() ? std::nullopt : std::optional(it->second);
        });
        step.note = text.steps()[i].note;
        step.picture.caption = cat(wordsFor(language).step, " ", i + 1, ": ", step.title);
    }

    for (const auto& [markdown, source] :
         {std::pair{&page.intro, introFile}, {&page.englishIntro, englishFile}})
        if (auto s = textPictures.add(*markdown, source); !s) return Error{s.error()};
    for (const auto* parts : {&page.before, &page.after})
        for (const Part& p : *parts)
            if (auto s = textPictures.add(p.text, p.englishOnly ? englishFile : ownFile); !s)
                return Error{s.error()};
    for (const StepPage& s : page.steps)
        if (auto added = textPictures.add(s.text, s.note.empty() ? ownFile : englishFile); !added)
            return Error{added.error()};
    return page;
}

Result<ContentsEntry> buildLesson(const fs::path& executable, const HandoutOptions& options,
                                  const fs::path& folder) {
    auto info = lessonOf(executable);
    if (!info) return Error{info.error()};
    const std::string name = lessonFolderName(*info);  // "06-bloom"
    const fs::path lessonFolder = lessonSourceFolder(*info);
    const fs::path work = folder / ".work";  // captures and logs; removed before the folder is done
    std::error_code ec;
    fs::create_directories(work, ec);
    if (ec) return Error{cat(work.string(), ": ", ec.message())};
    const fs::path dot = findProgram("dot");
    if (dot.empty())
        return Error{
            "Graphviz's dot is not on PATH: it draws the frame graphs (Debian: apt-get install graphviz; ./fxlab handout installs it)"};

    // Every step, captured by the lesson itself at a fixed moment of its headless clock.
    const auto started = std::chrono::steady_clock::now();
    options.progress(cat(name, ": capturing every step at ", toString(options.size), " (", options.frames,
                         " frames each)"));
    if (auto s = runLogged(executable,
                           {"--all-steps", "--headless", "--size", toString(options.size), "--frames",
                            std::to_string(options.frames), "--capture", (work / "captures").string()},
                           work / "capture.log", cat(name, ": capturing the steps"));
        !s)
        return Error{s.error()};
    auto captured = readCapturedSteps(work / "captures");
    if (!captured) return Error{captured.error()};
    if (captured->empty())
        return Error{cat(name, ": the capture wrote no step (", (work / "captures").string(), ")")};
    std::vector<std::string> titles;
    for (const CapturedStep& c : *captured) titles.push_back(c.report.value("stepTitle", std::string()));

    // The lesson's text, read as the overlay reads it.
    auto english = readLessonText(lessonFolder / "lesson.md");
    if (!english) return Error{english.error()};
    LessonTextFiles englishSteps(lessonFolder, titles, "en");
    (void)englishSteps.reloadIfChanged();
    if (!englishSteps.error().empty()) return Error{englishSteps.error()};
    auto steps = stepPages(*captured, englishSteps.steps(), options, dot, work, folder, name);
    if (!steps) return Error{steps.error()};

    // What accuracy costs, for a lesson with quality knobs: the bench's earlier results, or a run now.
    auto knobs = hasQualityKnobs(executable, work, name);
    if (!knobs) return Error{knobs.error()};
    BenchPart bench;
    if (*knobs) {
        fs::path benchFolder = options.benchRoot / name;
        if (options.withBench) {
            options.progress(cat(name, ": running the bench"));
            benchFolder = work / "bench";
            if (auto s = runLogged(executable, {"--bench", "--bench-out", benchFolder.string()},
                                   work / "bench.log", cat(name, ": the bench"));
                !s)
                return Error{s.error()};
        }
        auto found = readBench(benchFolder, folder);
        if (!found) return Error{cat(name, ": ", found.error())};
        bench = *found;
    }

    ContentsEntry entry{name, {}, int(captured->size())};
    TextPictures textPictures(lessonFolder, folder);
    std::vector<std::pair<std::string, std::string>> pages;
    for (const std::string& l : options.languages) pages.emplace_back(l, pageFileFor(l, options.languages));
    for (const std::string& language : options.languages) {
        auto page = lessonPage(language, *english, lessonFolder, titles, *steps, textPictures);
        if (!page) return Error{page.error()};
        page->languages = pages;
        page->madeWith = madeWith(language, captured->front().report, options.frames);
        page->bench = bench;
        entry.titles[language] = page->title;
        const std::string html = lessonPageHtml(*page, textPictures.source());
        if (auto s = writeFileAtomically(folder / pageFileFor(language, options.languages), html); !s)
            return Error{s.error()};
    }
    if (auto s = writeStyle(folder); !s) return Error{s.error()};
    fs::remove_all(work, ec);
    if (ec) return Error{cat(work.string(), ": ", ec.message())};
    const auto seconds =
        std::chrono::duration_cast<std::chrono::seconds>(std::chrono::steady_clock::now() - started).count();
    options.progress(cat(name, ": ", captured->size(), " steps written in ", seconds, " s"));
    return entry;
}

}  // namespace

Result<std::string> lessonFolderOf(const fs::path& executable) {
    auto info = lessonOf(executable);
    if (!info) return Error{info.error()};
    return lessonFolderName(*info);
}

Status writeStyle(const fs::path& folder) {
    auto text = readTextFile(resourceDir() / "handout" / "style.css");
    if (!text) return Error{text.error()};
    return writeFileAtomically(folder / "style.css", *text);
}

Status writeContents(const std::vector<ContentsEntry>& lessons, const std::vector<std::string>& languages,
                     const fs::path& folder) {
    std::vector<std::pair<std::string, std::string>> pages;
    for (const std::string& l : languages) pages.emplace_back(l, pageFileFor(l, languages));
    for (const auto& [language, file] : pages) {
        if (auto s = writeFileAtomically(folder / file, contentsPageHtml(lessons, language, pages, file)); !s)
            return s;
    }
    return writeStyle(folder);
}

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
