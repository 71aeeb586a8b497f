// The step sections of a lesson.md: parsed as written, then matched with the lesson's step titles.
#include <gtest/gtest.h>

#include "base/lesson_text.hpp"

namespace {

using fx::matchLessonText;
using fx::matchTranslation;
using fx::parseStepSections;

const std::vector<std::string> kTitles{"First", "Second", "Third"};

// The error of matching `markdown` with kTitles ("" when it matched).
std::string lessonError(const std::string& markdown) {
    auto sections = parseStepSections(markdown, "lesson.md");
    if (!sections) return sections.error();
    auto texts = matchLessonText(*sections, kTitles, "lesson.md");
    return texts ? std::string() : texts.error();
}

TEST(LessonText, StepSectionsBetweenOtherSectionsAndCode) {
    const std::string md =
        "# Lesson 09: test\n\nIntro.\n\n## The frame\n\n```\n## Step 9: inside code, not a heading\n```\n\n"
        "## Step 1: First\n\nOne **bold** line.\n\n### A sub-heading stays inside\n\nMore.\n\n"
        "## Step 2: Second\nTwo.\n\n\n## Step 3: Third\n\n- a\n- b\n\n## Tests\n\nNot a step.\n";
    auto sections = parseStepSections(md, "lesson.md");
    ASSERT_TRUE(sections.ok()) << sections.error();
    ASSERT_EQ(sections->size(), 3u);
    EXPECT_EQ((*sections)[0].number, 1);
    EXPECT_EQ((*sections)[0].title, "First");
    EXPECT_EQ((*sections)[0].text, "One **bold** line.\n\n### A sub-heading stays inside\n\nMore.");
    EXPECT_EQ((*sections)[0].line, 11);
    EXPECT_EQ((*sections)[1].text, "Two.");
    EXPECT_EQ((*sections)[2].text, "- a\n- b");
    auto texts = matchLessonText(*sections, kTitles, "lesson.md");
    ASSERT_TRUE(texts.ok()) << texts.error();
    EXPECT_EQ((*texts)[1], "Two.");
}

// The whole file in sections, for the handout: the title, the parts around the steps, and the steps.
TEST(LessonText, EverySectionInOrder) {
    const std::string md =
        "Before any heading.\n\n# Lesson 09: test\n\nIntro.\n\n## The frame\n\n```\n## Step 9: code\n```\n\n"
        "## Step 1: First\n\nOne.\n\n### Sub\n\nMore.\n\n## Tests\n\nNot a step.\n";
    auto sections = fx::parseLessonSections(md);
    ASSERT_EQ(sections.size(), 5u);
    EXPECT_EQ(sections[0].level, 0);
    EXPECT_EQ(sections[0].text, "Before any heading.");
    EXPECT_EQ(sections[1].level, 1);
    EXPECT_EQ(sections[1].heading, "Lesson 09: test");
    EXPECT_EQ(sections[1].text, "Intro.");
    EXPECT_EQ(sections[2].heading, "The frame");
    EXPECT_EQ(sections[2].text, "```\n## Step 9: code\n```");
    EXPECT_FALSE(fx::isStepSection(sections[2]));
    EXPECT_TRUE(fx::isStepSection(sections[3]));
    EXPECT_EQ(sections[3].text, "One.\n\n### Sub\n\nMore.");
    EXPECT_EQ(sections[3].line, 13);
    EXPECT_EQ(sections[4].heading, "Tests");
    // A file that starts with its title has no untitled part.
    EXPECT_EQ(fx::parseLessonSections("# T\n\nx\n").size(), 1u);
}

TEST(LessonText, WindowsLineEndingsAreRead) {
    auto sections = parseStepSections("## Step 1: First\r\n\r\nText.\r\n", "lesson.md");
    ASSERT_TRUE(sections.ok());
    ASSERT_EQ(sections->size(), 1u);
    EXPECT_EQ((*sections)[0].title, "First");
    EXPECT_EQ((*sections)[0].text, "Text.");
}

TEST(LessonText, NoSectionsNamesTheFirstStep) {
    EXPECT_EQ(lessonError("# Lesson\n\nOnly prose.\n"),
              "lesson.md: step 1 (\"First\") has no section; write \"## Step 1: First\" and its text");
}

TEST(LessonText, AMissingLastStepIsNamed) {
    EXPECT_NE(
        lessonError("## Step 1: First\na\n## Step 2: Second\nb\n").find("step 3 (\"Third\") has no section"),
        std::string::npos);
}

TEST(LessonText, DuplicateStep) {
    std::string e =
        lessonError("## Step 1: First\na\n## Step 2: Second\nb\n## Step 2: Second\nc\n## Step 3: Third\nd\n");
    EXPECT_EQ(e, "lesson.md:5: step 2 comes again after step 2; each step has one section, in order");
}

TEST(LessonText, OutOfOrderStep) {
    std::string e = lessonError("## Step 1: First\na\n## Step 3: Third\nc\n## Step 2: Second\nb\n");
    EXPECT_EQ(e, "lesson.md: step 2 (\"Second\") has no section; \"## Step 3\" at line 3 comes first");
}

TEST(LessonText, ExtraStep) {
    std::string e =
        lessonError("## Step 1: First\na\n## Step 2: Second\nb\n## Step 3: Third\nc\n## Step 4: Fourth\nd\n");
    EXPECT_EQ(e,
              "lesson.md:7: step 4: the lesson has 3 steps; remove this section or add the step to the "
              "lesson's code");
}

TEST(LessonText, EmptyText) {
    std::string e = lessonError("## Step 1: First\na\n## Step 2: Second\n\n\n## Step 3: Third\nc\n");
    EXPECT_EQ(e, "lesson.md:3: step 2 has no text");
}

TEST(LessonText, TitleDifferentFromTheCode) {
    std::string e = lessonError("## Step 1: First\na\n## Step 2: Secnd\nb\n## Step 3: Third\nc\n");
    EXPECT_EQ(e, "lesson.md:3: step 2: the heading's title \"Secnd\" is not the lesson's \"Second\"");
}

TEST(LessonText, MalformedHeadingsNameTheLine) {
    for (const char* heading :
         {"## Step two: x", "## Step 2 x", "## Step 2:", "## Step 0: x", "## Steps 2: x", "## Step 2a: x"}) {
        auto sections = parseStepSections(std::string("Intro\n") + heading + "\ntext\n", "l.md");
        ASSERT_FALSE(sections.ok()) << heading;
        EXPECT_NE(sections.error().find("l.md:2: "), std::string::npos) << sections.error();
        EXPECT_NE(sections.error().find("## Step N: title"), std::string::npos) << sections.error();
    }
}

TEST(LessonText, TranslationMayLackStepsButNotRepeatOrReorderThem) {
    auto sections = parseStepSections("## Step 1: 一\n一つ目。\n\n## Step 3: 三\n三つ目。\n", "lesson.ja.md");
    ASSERT_TRUE(sections.ok());
    auto byStep = matchTranslation(*sections, 3, "lesson.ja.md");
    ASSERT_TRUE(byStep.ok()) << byStep.error();
    ASSERT_EQ(byStep->size(), 3u);
    EXPECT_EQ((*byStep)[0]->title, "一");
    EXPECT_EQ((*byStep)[1], nullptr);
    EXPECT_EQ((*byStep)[2]->text, "三つ目。");

    auto error = [](const std::string& md) {
        auto s = parseStepSections(md, "lesson.ja.md");
        auto m = matchTranslation(*s, 3, "lesson.ja.md");
        return m ? std::string() : m.error();
    };
    EXPECT_EQ(error("## Step 2: b\nx\n## Step 2: b\ny\n"),
              "lesson.ja.md:3: step 2 comes after step 2; each step has at most one section, in order");
    EXPECT_EQ(error("## Step 3: c\nx\n## Step 1: a\ny\n"),
              "lesson.ja.md:3: step 1 comes after step 3; each step has at most one section, in order");
    EXPECT_EQ(error("## Step 4: d\nx\n"), "lesson.ja.md:1: step 4: the lesson has 3 steps");
    EXPECT_EQ(error("## Step 1: a\n\n## Step 2: b\nx\n"), "lesson.ja.md:1: step 1 has no text");
}

// A translation heads its sections in its own words: "## ステップ N: title" is a step's section and
// "## 確認課題 N: title" a checked exercise's, read as the English headings are; a malformed one is
// an error that names the Japanese form.
TEST(LessonText, JapaneseHeadingsAreStepsAndCheckedExercises) {
    const std::string md =
        "# レッスン 01：テスト\n\n## 章の課題\n\n課題01。\n\n## ステップ 1: 一つ目\n一。\n\n"
        "## Step 2: 二つ目\n二。\n\n## 確認課題 1: 積の順序\n確認。\n";
    auto steps = parseStepSections(md, "lesson.ja.md");
    ASSERT_TRUE(steps.ok()) << steps.error();
    ASSERT_EQ(steps->size(), 2u);
    EXPECT_EQ((*steps)[0].number, 1);
    EXPECT_EQ((*steps)[0].title, "一つ目");
    EXPECT_EQ((*steps)[0].text, "一。");
    EXPECT_EQ((*steps)[1].title, "二つ目");
    auto exercises = parseStepSections(md, "lesson.ja.md", "Checked exercise");
    ASSERT_TRUE(exercises.ok()) << exercises.error();
    ASSERT_EQ(exercises->size(), 1u);
    EXPECT_EQ((*exercises)[0].title, "積の順序");
    EXPECT_EQ((*exercises)[0].text, "確認。");
    // The part before the steps is no step, in either language.
    const auto sections = fx::parseLessonSections(md);
    ASSERT_EQ(sections.size(), 5u);
    EXPECT_FALSE(fx::isStepSection(sections[1]));
    EXPECT_TRUE(fx::isStepSection(sections[2]));
    EXPECT_TRUE(fx::isStepSection(sections[4], "Checked exercise"));

    auto bad = parseStepSections("## ステップ一: x\ntext\n", "lesson.ja.md");
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(
        bad.error(),
        "lesson.ja.md:1: \"## ステップ一: x\" is not a step heading; write \"## ステップ N: title\" (N from 1)");
}

// The pages beside the steps: every "## " section that is neither a step nor a checked exercise, in
// either language's headings, in order; "### " stays inside its section, code is not a heading.
TEST(LessonText, PagesAreTheSectionsBesideTheSteps) {
    const auto pages = fx::lessonPages(
        "# Lesson 01: x\n\nIntro.\n\n## The frame\n\nFrame.\n\n## Step 1: First\n\nOne.\n\n### Exercise\n\nIn step 1."
        "\n\n## ステップ 2: 二\n\n二。\n\n## Pitfalls\n\n```\n## Step 9: code\n```\n\n## Checked exercise 1: Mine\n\n"
        "Check.\n\n## 確認課題 2: 自分の\n\n確認。\n\n## 章の課題02\n\n課題。\n");
    ASSERT_EQ(pages.size(), 3u);
    EXPECT_EQ(pages[0].heading, "The frame");
    EXPECT_EQ(pages[0].text, "Frame.");
    EXPECT_EQ(pages[1].heading, "Pitfalls");
    EXPECT_EQ(pages[1].text, "```\n## Step 9: code\n```");
    EXPECT_EQ(pages[2].heading, "章の課題02");
    EXPECT_TRUE(fx::lessonPages("## Step 1: First\n\nOne.\n").empty());
}

}  // namespace
