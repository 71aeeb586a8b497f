#pragma once
// The handout's pages as HTML, from what was gathered about a lesson (handout_build.hpp gathers it):
// no file access here, so every part of a page has a unit test. A page needs no script and loads
// nothing from elsewhere: its pictures and its one stylesheet (style.css) sit beside it. Each step
// starts a printed page (the stylesheet's print rules).
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/handout_html.hpp"

namespace fx::handout {

struct Picture {
    std::string file;  // relative to the page
    std::string caption;
    int width = 0, height = 0;  // 0: not known
};

// A texture the step's text points at, or a chain of them (bloom.down[0..5]) shown as a strip.
struct View {
    std::string title;
    std::vector<Picture> pictures;
};

struct StepPage {
    int number = 0;
    std::string title, text, note;  // the text is markdown, as the overlay shows it
    Picture picture;
    std::vector<std::pair<std::string, std::string>> facts;  // label, value
    // Every fact of the run by name, shown or not: the text's {fact:NAME} references read them.
    std::map<std::string, std::string> factValues;
    std::vector<View> views;
    // Where the step changes the frame: the graph's picture and the report's passes. Otherwise
    // sameFrameAs names the earlier step whose frame this is.
    std::string graphFile;
    int graphWidth = 0, graphHeight = 0;
    nlohmann::ordered_json passes = nlohmann::ordered_json::array();
    int sameFrameAs = 0;
};

// A "## heading" part of lesson.md that is not a step (The frame, Tests, Hard cases, ...).
struct Part {
    std::string heading, text;  // markdown
    bool englishOnly = false;   // shown on a page of another language
};

struct BenchRow {
    std::string knob, value;
    bool reference = false, current = false;
    double cost = 0;  // full-screen copies (or ms when costUnit says so)
    double rmse = 0;
};

struct BenchPart {
    bool applicable = false;   // the lesson has quality knobs to sweep
    bool found = false;        // and the bench's results were there
    std::string size, timing;  // "1280x720", "glFinish + wall clock"
    double copyMs = 0;         // one full-screen copy, the unit of the cost column; 0: the cost is in ms
    std::vector<Picture> plots;
    std::vector<BenchRow> rows;
};

struct LessonPage {
    std::string language;                                        // of this page
    std::vector<std::pair<std::string, std::string>> languages;  // every language's page: name, file
    std::string title;                                           // lesson.md's "# " heading
    std::string intro;                                           // markdown under it
    std::string englishIntro;                                    // on a page of another language
    std::string madeWith;                                        // how the pictures were made
    std::vector<Part> before, after;                             // parts before the first step and after it
    std::vector<StepPage> steps;
    BenchPart bench;
};

std::string lessonPageHtml(const LessonPage& page, const PictureSource& textPictures);

// The pass table of one frame: a column for every key the report's passes have (known keys in the
// page's words, others spelled out), without the columns that are empty in every row; a column whose
// value is the same in every row is said once under the table instead.
std::string passTableHtml(const nlohmann::ordered_json& passes, const std::string& language);

struct ContentsEntry {
    std::string folder;                         // "06-bloom"
    std::map<std::string, std::string> titles;  // per language: the lesson's "# " heading
    int steps = 0;
};

// The contents page of `./fxlab handout --all`: every lesson's page in this language.
std::string contentsPageHtml(const std::vector<ContentsEntry>& lessons, const std::string& language,
                             const std::vector<std::pair<std::string, std::string>>& languages,
                             const std::string& lessonPageFile);

// The page file of a language: the first language's page is index.html, the others index.<lang>.html.
std::string pageFileFor(const std::string& language, const std::vector<std::string>& languages);

}  // namespace fx::handout
