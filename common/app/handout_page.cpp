#include "app/handout_page.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "app/handout_words.hpp"

namespace fx::handout {
namespace {

using json = nlohmann::ordered_json;

std::string number(double v) {
    if (!std::isfinite(v)) return v != v ? "NaN" : (v > 0 ? "inf" : "-inf");
    char text[32];
    const double a = std::fabs(v);
    // Three significant digits below 100 (0.0481, 3.25, 12.4), whole numbers as they are.
    std::snprintf(text, sizeof text,
                  a >= 100 || v == std::floor(v) ? "%.0f"
                  : a >= 10                      ? "%.1f"
                  : a >= 1                       ? "%.2f"
                                                 : "%.3g",
                  v);
    return text;
}

// A report value as a cell's text: lists joined, objects as key: value, null as nothing.
std::string valueText(const json& v) {
    if (v.is_null()) return {};
    if (v.is_string()) return v.get<std::string>();
    if (v.is_boolean()) return v.get<bool>() ? "yes" : "no";
    if (v.is_number()) return number(v.get<double>());
    std::string out;
    if (v.is_array()) {
        for (const json& e : v) out += (out.empty() ? "" : ", ") + valueText(e);
        return out;
    }
    for (auto it = v.begin(); it != v.end(); ++it)
        out += (out.empty() ? "" : ", ") + it.key() + ": " + valueText(it.value());
    return out;
}

std::string pictureHtml(const Picture& p, const std::string& extraClass = {}) {
    std::string size;
    if (p.width > 0 && p.height > 0)
        size = " width=\"" + std::to_string(p.width) + "\" height=\"" + std::to_string(p.height) + "\"";
    std::string out =
        "<figure" + (extraClass.empty() ? std::string() : " class=\"" + extraClass + "\"") + ">";
    out += "<img src=\"" + escapeHtml(p.file) + "\" alt=\"" + escapeHtml(p.caption) + "\"" + size + ">";
    if (!p.caption.empty()) out += "<figcaption>" + escapeHtml(p.caption) + "</figcaption>";
    return out + "</figure>\n";
}

std::string languageLinks(const std::vector<std::pair<std::string, std::string>>& languages,
                          const std::string& current) {
    std::string out;
    for (const auto& [language, file] : languages) {
        if (language == current) continue;
        out += " · <a href=\"" + escapeHtml(file) + "\" hreflang=\"" + language + "\" lang=\"" + language +
               "\">" + escapeHtml(wordsFor(language).languageName) + "</a>";
    }
    return out;
}

std::string head(const std::string& language, const std::string& title) {
    return "<!DOCTYPE html>\n<html lang=\"" + language +
           "\">\n<head>\n<meta charset=\"utf-8\">\n"
           "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>" +
           escapeHtml(title) + "</title>\n<link rel=\"stylesheet\" href=\"style.css\">\n</head>\n<body>\n";
}

std::string partHtml(const Part& part, const std::string& id, const Words& words,
                     const PictureSource& pictures) {
    std::string out =
        "<section class=\"part\" id=\"" + id + "\"" + (part.englishOnly ? " lang=\"en\"" : "") + ">\n";
    out += "<h2>" + escapeHtml(part.heading) + "</h2>\n";
    if (part.englishOnly)
        out +=
            "<p class=\"note\" lang=\"" + words.language + "\">" + escapeHtml(words.englishOnly) + "</p>\n";
    out += markdownToHtml(part.text, pictures, 3);
    return out + "</section>\n";
}

std::string factsHtml(const StepPage& step, const Words& words) {
    if (step.facts.empty()) return {};
    std::string out =
        "<div class=\"facts\">\n<h3>" + escapeHtml(words.facts) + "</h3>\n<table class=\"facts-table\">\n";
    for (const auto& [label, value] : step.facts)
        out +=
            "<tr><th scope=\"row\">" + escapeHtml(label) + "</th><td>" + escapeHtml(value) + "</td></tr>\n";
    return out + "</table>\n</div>\n";
}

std::string viewsHtml(const StepPage& step, const Words& words) {
    if (step.views.empty()) return {};
    std::string out = "<div class=\"views\">\n<h3>" + escapeHtml(words.inspector) + "</h3>\n";
    for (const View& v : step.views) {
        if (v.pictures.size() == 1) {
            out += pictureHtml(v.pictures.front(), "view");
            continue;
        }
        out += "<figure class=\"strip\">\n<div class=\"strip-levels\">\n";
        for (const Picture& p : v.pictures) out += pictureHtml(p, "level");
        out += "</div>\n<figcaption>" + escapeHtml(v.title) + "</figcaption>\n</figure>\n";
    }
    return out + "</div>\n";
}

std::string frameHtml(const StepPage& step, const Words& words, const std::string& language) {
    if (step.sameFrameAs > 0) {
        return "<p class=\"same-frame\">" + escapeHtml(words.sameFrame) + "<a href=\"#step-" +
               std::to_string(step.sameFrameAs) + "\">" + std::to_string(step.sameFrameAs) + "</a>" +
               escapeHtml(words.sameFrameEnd) + "</p>\n";
    }
    std::string out = "<div class=\"frame\">\n";
    if (!step.graphFile.empty()) {
        out += "<h3>" + escapeHtml(words.frameGraph) + "</h3>\n";
        out += pictureHtml({step.graphFile, {}, step.graphWidth, step.graphHeight}, "graph");
    }
    if (!step.passes.empty()) {
        out += "<h3>" + escapeHtml(words.passTable) + "</h3>\n";
        out += passTableHtml(step.passes, language);
    }
    return out + "</div>\n";
}

std::string stepHtml(const StepPage& step, const Words& words, const std::string& language,
                     const PictureSource& pictures) {
    const std::string n = std::to_string(step.number);
    std::string out = "<section class=\"step\" id=\"step-" + n + "\">\n";
    out += "<h2><span class=\"step-number\">" + escapeHtml(words.step) + " " + n + "</span> " +
           escapeHtml(step.title) + "</h2>\n";
    out += pictureHtml(step.picture, "step-picture");
    if (!step.note.empty()) out += "<p class=\"note\">" + escapeHtml(step.note) + "</p>\n";
    out += "<div class=\"step-text\">\n" + markdownToHtml(step.text, pictures, 3) + "</div>\n";
    out += factsHtml(step, words);
    out += viewsHtml(step, words);
    out += frameHtml(step, words, language);
    return out + "</section>\n";
}

std::string benchHtml(const BenchPart& bench, const Words& words) {
    if (!bench.applicable) return {};
    std::string out =
        "<section class=\"part bench\" id=\"bench\">\n<h2>" + escapeHtml(words.bench) + "</h2>\n";
    if (!bench.found)
        return out + "<p class=\"note\">" + escapeHtml(words.benchMissing) + "</p>\n</section>\n";
    std::string setting = bench.size + ", " + bench.timing;
    if (bench.copyMs > 0) setting += ", 1 copy = " + number(bench.copyMs) + " ms";
    out += "<p>" + escapeHtml(words.benchMeasured + setting) + "</p>\n";
    for (const Picture& p : bench.plots) out += pictureHtml(p, "plot");
    out += "<table class=\"bench-table\">\n<thead><tr><th>" + escapeHtml(words.knob) + "</th><th>" +
           escapeHtml(words.value) + "</th><th>" +
           escapeHtml(bench.copyMs > 0 ? words.costCopies : words.costMs) +
           "</th><th>RMSE</th></tr></thead>\n<tbody>\n";
    for (const BenchRow& r : bench.rows) {
        std::string value = escapeHtml(r.value);
        if (r.reference) value += " <span class=\"mark\">(" + escapeHtml(words.reference) + ")</span>";
        if (r.current) value += " <span class=\"mark\">(" + escapeHtml(words.current) + ")</span>";
        out += "<tr><td>" + escapeHtml(r.knob) + "</td><td>" + value + "</td><td class=\"number\">" +
               number(r.cost) + "</td><td class=\"number\">" + number(r.rmse) + "</td></tr>\n";
    }
    return out + "</tbody>\n</table>\n</section>\n";
}

}  // namespace

std::string pageFileFor(const std::string& language, const std::vector<std::string>& languages) {
    return languages.empty() || languages.front() == language ? "index.html" : "index." + language + ".html";
}

namespace {

// The report's cost model (trafficBytes1080p's read and written bytes, taps) as the overlay's pass
// table words it, in one narrow column: "37.3/9" (MB at 1920x1080 / taps per pixel written). Raw
// byte counts in two columns made a printed page wider than A4.
json withModelColumn(const json& passes) {
    json out = json::array();
    for (const json& p : passes) {
        json row = json::object();
        for (auto it = p.begin(); it != p.end(); ++it) {
            if (it.key() == "taps") continue;
            if (it.key() != "trafficBytes1080p") {
                row[it.key()] = it.value();
                continue;
            }
            const json& t = it.value();
            const bool runs = p.value("status", std::string()) == "runs";
            if (!runs || !t.is_object()) continue;
            const std::uint64_t bytes =
                t.value("read", std::uint64_t(0)) + t.value("written", std::uint64_t(0));
            const json taps = p.value("taps", json());
            char mb[32];
            std::snprintf(mb, sizeof mb, "%.1f", double(bytes) / 1e6);
            row["modelledMbTaps"] = std::string(mb) + "/" + (taps.is_number() ? valueText(taps) : "-");
        }
        out.push_back(std::move(row));
    }
    return out;
}

}  // namespace

std::string passTableHtml(const json& reportPasses, const std::string& language) {
    const Words& words = wordsFor(language);
    const json passes = withModelColumn(reportPasses);
    // The columns: every key any pass has, in the order the report writes them. "executed" says
    // again what "status" says.
    std::vector<std::string> keys;
    for (const json& p : passes) {
        for (auto it = p.begin(); it != p.end(); ++it) {
            if (it.key() == "executed") continue;
            if (std::find(keys.begin(), keys.end(), it.key()) == keys.end()) keys.push_back(it.key());
        }
    }
    std::vector<std::string> columns, same;
    for (const std::string& key : keys) {
        bool anyText = false, allSame = passes.size() > 1;
        const std::string first =
            passes.empty() ? std::string() : valueText(passes.front().value(key, json()));
        for (const json& p : passes) {
            const std::string text = valueText(p.value(key, json()));
            anyText = anyText || !text.empty();
            allSame = allSame && text == first;
        }
        if (!anyText) continue;
        if (allSame && key != "name") {
            same.push_back(columnName(key, language) + ": " + first);
        } else {
            columns.push_back(key);
        }
    }
    std::string out = "<table class=\"pass-table\">\n<thead><tr>";
    for (const std::string& key : columns) out += "<th>" + escapeHtml(columnName(key, language)) + "</th>";
    out += "</tr></thead>\n<tbody>\n";
    for (const json& p : passes) {
        const auto executed = p.find("executed");
        const bool ran = executed == p.end() || !executed->is_boolean() || executed->get<bool>();
        out += ran ? "<tr>" : "<tr class=\"not-run\">";
        for (const std::string& key : columns) {
            const json& v = p.value(key, json());
            out += (v.is_number() ? "<td class=\"number\">" : "<td>") + escapeHtml(valueText(v)) + "</td>";
        }
        out += "</tr>\n";
    }
    out += "</tbody>\n</table>\n";
    if (std::find(columns.begin(), columns.end(), "modelledMbTaps") != columns.end())
        out += "<p class=\"table-note\">" + escapeHtml(words.modelledColumn) + "</p>\n";
    if (!same.empty()) {
        out += "<p class=\"table-note\">" + escapeHtml(words.sameForAllPasses) + ": ";
        for (std::size_t i = 0; i < same.size(); ++i) out += (i ? "; " : "") + escapeHtml(same[i]);
        out += "</p>\n";
    }
    return out;
}

std::string lessonPageHtml(const LessonPage& page, const PictureSource& pictures) {
    const Words& words = wordsFor(page.language);
    std::string out = head(page.language, page.title + " — " + words.handout);
    out += "<header class=\"cover\">\n<p class=\"kicker\">" + escapeHtml(words.handout) +
           languageLinks(page.languages, page.language) + "</p>\n";
    out += "<h1>" + escapeHtml(page.title) + "</h1>\n";
    out += "<div class=\"intro\">\n" + markdownToHtml(page.intro, pictures, 3) + "</div>\n";
    if (!page.englishIntro.empty())
        out += "<div class=\"intro\" lang=\"en\">\n" + markdownToHtml(page.englishIntro, pictures, 3) +
               "</div>\n";
    out += "<p class=\"made\">" + escapeHtml(words.picturesMade + page.madeWith) + "</p>\n";
    out += "<nav class=\"toc\">\n<h2>" + escapeHtml(words.contents) + "</h2>\n<ol>\n";
    for (std::size_t i = 0; i < page.before.size(); ++i)
        out += "<li><a href=\"#before-" + std::to_string(i + 1) + "\">" + escapeHtml(page.before[i].heading) +
               "</a></li>\n";
    for (const StepPage& s : page.steps)
        out += "<li><a href=\"#step-" + std::to_string(s.number) + "\">" + escapeHtml(words.step) + " " +
               std::to_string(s.number) + ": " + escapeHtml(s.title) + "</a></li>\n";
    if (page.bench.applicable) out += "<li><a href=\"#bench\">" + escapeHtml(words.bench) + "</a></li>\n";
    for (std::size_t i = 0; i < page.after.size(); ++i)
        out += "<li><a href=\"#after-" + std::to_string(i + 1) + "\">" + escapeHtml(page.after[i].heading) +
               "</a></li>\n";
    out += "</ol>\n</nav>\n</header>\n<main>\n";
    for (std::size_t i = 0; i < page.before.size(); ++i)
        out += partHtml(page.before[i], "before-" + std::to_string(i + 1), words, pictures);
    for (const StepPage& s : page.steps) out += stepHtml(s, words, page.language, pictures);
    out += "<div class=\"after\">\n" + benchHtml(page.bench, words);
    for (std::size_t i = 0; i < page.after.size(); ++i)
        out += partHtml(page.after[i], "after-" + std::to_string(i + 1), words, pictures);
    out += "</div>\n</main>\n</body>\n</html>\n";
    return out;
}

std::string contentsPageHtml(const std::vector<ContentsEntry>& lessons, const std::string& language,
                             const std::vector<std::pair<std::string, std::string>>& languages,
                             const std::string& lessonPageFile) {
    const Words& words = wordsFor(language);
    std::string out = head(language, words.handout + ": " + words.lessons);
    out += "<header class=\"cover\">\n<p class=\"kicker\">" + escapeHtml(words.handout) +
           languageLinks(languages, language) + "</p>\n<h1>" + escapeHtml(words.lessons) +
           "</h1>\n</header>\n";
    out += "<main>\n<ol class=\"lessons\">\n";
    for (const ContentsEntry& e : lessons) {
        auto title = e.titles.find(language);
        if (title == e.titles.end()) title = e.titles.find("en");
        const std::string text = title == e.titles.end() ? e.folder : title->second;
        out += "<li><a href=\"" + escapeHtml(e.folder + "/" + lessonPageFile) + "\">" + escapeHtml(text) +
               "</a> <span class=\"count\">(" + std::to_string(e.steps) + " " + escapeHtml(words.stepsCount) +
               ")</span></li>\n";
    }
    return out + "</ol>\n</main>\n</body>\n</html>\n";
}

}  // namespace fx::handout
