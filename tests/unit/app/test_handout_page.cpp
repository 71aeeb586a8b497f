// The handout's pages (app/handout_page.hpp) from what the builder gathered: no files involved.
#include <gtest/gtest.h>

#include "app/handout_page.hpp"

namespace {

using namespace fx::handout;
using json = nlohmann::ordered_json;

bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

json passes() {
    return json::parse(R"([
      {"name": "scene", "executed": true, "status": "executed", "reason": "", "timeMs": 3.25, "timingMethod": "fenced",
       "reads": [], "writes": ["scene.color", "scene.depth"], "stateLeft": "", "trafficBytes": 1500000},
      {"name": "bloom <down>", "executed": false, "status": "culled", "reason": "nothing reads bloom.down[1]",
       "timeMs": null, "timingMethod": "fenced", "reads": ["scene.color"], "writes": ["bloom.down[1]"], "stateLeft": "",
       "trafficBytes": 0}
    ])");
}

TEST(HandoutPage, ThePassTableShowsWhatTheReportHas) {
    const std::string table = passTableHtml(passes(), "en");
    // Known keys in words, a key the report gained later spelled out, columns empty in every row left out,
    // and one that is the same in every row said once.
    EXPECT_TRUE(has(table,
                    "<th>pass</th><th>status</th><th>why it did not run</th><th>ms</th><th>reads</th>"
                    "<th>writes</th><th>traffic bytes</th></tr>"))
        << table;
    EXPECT_FALSE(has(table, "state left"));
    EXPECT_FALSE(has(table, "<th>executed"));
    EXPECT_TRUE(has(table, "<p class=\"table-note\">for every pass: timed by: fenced</p>"));
    EXPECT_TRUE(has(table, "<td>scene.color, scene.depth</td>"));
    EXPECT_TRUE(has(table, "<td class=\"number\">3.25</td>"));
    EXPECT_TRUE(has(table, "<td class=\"number\">1500000</td>"));
    EXPECT_TRUE(
        has(table, "<tr class=\"not-run\"><td>bloom &lt;down&gt;</td><td>culled</td><td>nothing reads "));
    EXPECT_TRUE(has(passTableHtml(passes(), "ja"), "<th>パス</th><th>状況</th><th>実行しなかった理由</th>"));
}

LessonPage page() {
    LessonPage p;
    p.language = "en";
    p.languages = {{"en", "index.html"}, {"ja", "index.ja.html"}};
    p.title = "Lesson 06: bloom";
    p.intro = "From the **Bloom** chapter.";
    p.madeWith = "1280x720, frame 3";
    p.before = {{"The frame", "```\nscene -> bloom\n```", false}};
    p.after = {{"Tests", "- `tests/gl/x.cpp`", false}};
    StepPage one;
    one.number = 1;
    one.title = "An 8-bit target";
    one.text = "Inspect `scene.color`.";
    one.picture = {"step-1.png", "Step 1: An 8-bit target", 1280, 720};
    one.facts = {{"levels", "6"}};
    one.views = {{"bloom.down[0 .. 1]",
                  {{"step-1-bloom.down-0.png", "bloom.down[0] 640x360", 640, 360},
                   {"step-1-bloom.down-1.png", "bloom.down[1] 320x180", 320, 180}}}};
    one.graphFile = "step-1-graph.svg";
    one.passes = passes();
    StepPage two = one;
    two.number = 2;
    two.title = "The same frame";
    two.views.clear();
    two.facts.clear();
    two.graphFile.clear();
    two.passes = json::array();
    two.sameFrameAs = 1;
    p.steps = {one, two};
    return p;
}

TEST(HandoutPage, TheLessonPageHasEveryPartInOrder) {
    const std::string html = lessonPageHtml(page(), [](const std::string& t) { return t; });
    EXPECT_TRUE(has(html, "<html lang=\"en\">"));
    EXPECT_TRUE(has(html, "<link rel=\"stylesheet\" href=\"style.css\">"));
    EXPECT_FALSE(has(html, "<script"));
    EXPECT_FALSE(has(html, "http"));  // nothing fetched from elsewhere
    EXPECT_TRUE(has(html, "<a href=\"index.ja.html\" hreflang=\"ja\" lang=\"ja\">日本語</a>"));
    EXPECT_TRUE(has(html, "<p>From the <strong>Bloom</strong> chapter.</p>"));
    const std::size_t frame = html.find("id=\"before-1\""), step1 = html.find("id=\"step-1\""),
                      step2 = html.find("id=\"step-2\""), tests = html.find("id=\"after-1\"");
    ASSERT_NE(frame, std::string::npos);
    EXPECT_LT(frame, step1);
    EXPECT_LT(step1, step2);
    EXPECT_LT(step2, tests);
    EXPECT_TRUE(has(html, "<a href=\"#step-2\">Step 2: The same frame</a>"));
    EXPECT_TRUE(
        has(html, "<img src=\"step-1.png\" alt=\"Step 1: An 8-bit target\" width=\"1280\" height=\"720\">"));
    EXPECT_TRUE(has(html, "<tr><th scope=\"row\">levels</th><td>6</td></tr>"));
    EXPECT_TRUE(has(html, "<figure class=\"strip\">"));
    EXPECT_TRUE(has(html, "step-1-bloom.down-1.png"));
    EXPECT_TRUE(has(html, "<img src=\"step-1-graph.svg\""));
    // Step 2 draws the same frame: a link back instead of the graph and table again.
    EXPECT_TRUE(has(html.substr(step2),
                    "The frame graph and the passes are those of step <a href=\"#step-1\">1</a>."));
    EXPECT_FALSE(has(html.substr(step2, tests - step2), "pass-table"));
    // A lesson without quality knobs has no bench part at all.
    EXPECT_FALSE(has(html, "id=\"bench\""));
}

TEST(HandoutPage, TheBenchPartSaysWhatItFoundOrHowToMakeIt) {
    LessonPage p = page();
    p.bench.applicable = true;
    std::string html = lessonPageHtml(p, {});
    EXPECT_TRUE(has(html, "No bench results were found for this lesson"));
    p.bench.found = true;
    p.bench.size = "1280x720";
    p.bench.timing = "glFinish + wall clock";
    p.bench.copyMs = 3.3512;
    p.bench.plots = {{"bench-levels.png", "levels", 0, 0}};
    p.bench.rows = {{"levels", "6", true, true, 9.04, 0.048}};
    html = lessonPageHtml(p, {});
    EXPECT_TRUE(has(html, "<img src=\"bench-levels.png\" alt=\"levels\">"));
    EXPECT_TRUE(has(html, "Measured by ./fxlab bench at 1280x720, glFinish + wall clock, 1 copy = 3.35 ms"));
    EXPECT_TRUE(has(html, "<th>frame (full-screen copies)</th>"));
    EXPECT_TRUE(has(html,
                    "<td>6 <span class=\"mark\">(reference)</span> <span class=\"mark\">(default)</span></td>"
                    "<td class=\"number\">9.04</td><td class=\"number\">0.048</td>"));
}

TEST(HandoutPage, AJapanesePageNamesItsLanguageAndMarksEnglishParts) {
    LessonPage p = page();
    p.language = "ja";
    p.after.front().englishOnly = true;
    p.englishIntro = "From the chapter.";
    const std::string html = lessonPageHtml(p, {});
    EXPECT_TRUE(has(html, "<html lang=\"ja\">"));
    EXPECT_TRUE(has(html, "<a href=\"index.html\" hreflang=\"en\" lang=\"en\">English</a>"));
    EXPECT_TRUE(has(html, "<span class=\"step-number\">ステップ 1</span>"));
    EXPECT_TRUE(has(html, "<section class=\"part\" id=\"after-1\" lang=\"en\">"));
    EXPECT_TRUE(has(html, "この部分は英語のみです"));
    EXPECT_TRUE(has(html, "<div class=\"intro\" lang=\"en\">"));
    EXPECT_TRUE(has(html, "フレームグラフとパスはステップ <a href=\"#step-1\">1</a> と同じです。"));
}

TEST(HandoutPage, TheContentsPageLinksEveryLessonInItsLanguage) {
    std::vector<ContentsEntry> lessons{
        {"01-program-objects", {{"en", "Lesson 01: program objects"}, {"ja", "レッスン 01"}}, 5},
        {"02-skinned-shadows", {{"en", "Lesson 02"}}, 5}};
    const std::vector<std::pair<std::string, std::string>> pages{{"en", "index.html"},
                                                                 {"ja", "index.ja.html"}};
    const std::string ja = contentsPageHtml(lessons, "ja", pages, "index.ja.html");
    EXPECT_TRUE(has(ja, "<a href=\"01-program-objects/index.ja.html\">レッスン 01</a>"));
    EXPECT_TRUE(
        has(ja, "<a href=\"02-skinned-shadows/index.ja.html\">Lesson 02</a>"));  // no translated title
    EXPECT_TRUE(has(contentsPageHtml(lessons, "en", pages, "index.html"), "(5 steps)"));
    EXPECT_EQ(pageFileFor("ja", {"en", "ja"}), "index.ja.html");
    EXPECT_EQ(pageFileFor("ja", {"ja", "en"}), "index.html");
}

}  // namespace
