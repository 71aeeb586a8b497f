// A lesson's text files as the overlay sees them: read, matched with the steps, read again when
// changed (keeping the last good text on an error), a translation with English for what it lacks.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "../image/temp_folder.hpp"
#include "app/lesson_text_files.hpp"
#include "app/run_options.hpp"

namespace {

namespace fs = std::filesystem;
using fx::LessonTextFiles;

const std::vector<std::string> kTitles{"First", "Second"};
const char* kEnglish = "# Lesson\n\n## Step 1: First\n\nOne.\n\n## Step 2: Second\n\nTwo.\n";

void write(const fs::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
    // A later write must look changed even within the file system's time resolution.
    static auto stamp = fs::file_time_type::clock::now();
    stamp += std::chrono::seconds(2);
    fs::last_write_time(path, stamp);
}

TEST(LessonTextFiles, ReadsTheStepsAndKeepsTheLastGoodTextOnAnError) {
    fx::test::TempFolder dir;
    write(dir.path() / "lesson.md", kEnglish);
    LessonTextFiles text(dir.path(), kTitles);
    EXPECT_TRUE(text.reloadIfChanged());
    EXPECT_FALSE(text.reloadIfChanged());  // nothing changed
    ASSERT_EQ(text.steps().size(), 2u);
    EXPECT_EQ(text.steps()[0].title, "First");
    EXPECT_EQ(text.steps()[1].text, "Two.");
    EXPECT_TRUE(text.error().empty());

    const int revision = text.revision();
    write(dir.path() / "lesson.md", "## Step 1: First\n\nOne, edited.\n");  // step 2 gone
    EXPECT_TRUE(text.reloadIfChanged());
    EXPECT_NE(text.error().find("lesson.md: step 2 (\"Second\") has no section"), std::string::npos)
        << text.error();
    EXPECT_EQ(text.steps()[0].text, "One.");  // what was read before stays
    EXPECT_GT(text.revision(), revision);

    write(dir.path() / "lesson.md", "## Step 1: First\n\nOne, edited.\n\n## Step 2: Second\n\nTwo.\n");
    EXPECT_TRUE(text.reloadIfChanged());
    EXPECT_TRUE(text.error().empty()) << text.error();
    EXPECT_EQ(text.steps()[0].text, "One, edited.");
}

TEST(LessonTextFiles, AMissingLessonMdShowsTitlesOnlyAndSaysWhichFile) {
    fx::test::TempFolder dir;
    LessonTextFiles text(dir.path(), kTitles);
    (void)text.reloadIfChanged();
    ASSERT_EQ(text.steps().size(), 2u);
    EXPECT_EQ(text.steps()[1].title, "Second");
    EXPECT_TRUE(text.steps()[1].text.empty());
    EXPECT_NE(text.error().find((dir.path() / "lesson.md").string()), std::string::npos) << text.error();
    EXPECT_NE(text.error().find("titles only"), std::string::npos) << text.error();
}

TEST(LessonTextFiles, TranslationFallsBackToEnglishPerStep) {
    fx::test::TempFolder dir;
    write(dir.path() / "lesson.md", kEnglish);
    write(dir.path() / "lesson.ja.md", "## Step 2: 二つ目\n\n二。\n");
    LessonTextFiles text(dir.path(), kTitles, "ja");
    (void)text.reloadIfChanged();
    EXPECT_TRUE(text.error().empty()) << text.error();
    EXPECT_EQ(text.translatedSteps(), 1);
    EXPECT_EQ(text.steps()[0].title, "First");
    EXPECT_EQ(text.steps()[0].text, "One.");
    EXPECT_NE(text.steps()[0].note.find("lesson.ja.md"), std::string::npos);
    EXPECT_EQ(text.steps()[1].title, "二つ目");
    EXPECT_EQ(text.steps()[1].text, "二。");
    EXPECT_TRUE(text.steps()[1].note.empty());
    EXPECT_EQ(text.available(), (std::vector<std::string>{"en", "ja"}));

    EXPECT_TRUE(text.setLanguage("en").ok());
    EXPECT_EQ(text.steps()[1].title, "Second");
    EXPECT_TRUE(text.steps()[1].note.empty());
    EXPECT_FALSE(text.setLanguage("fr").ok());
    EXPECT_EQ(text.language(), "en");
}

TEST(LessonTextFiles, ABrokenTranslationIsAnErrorNamingItsFile) {
    fx::test::TempFolder dir;
    write(dir.path() / "lesson.md", kEnglish);
    write(dir.path() / "lesson.ja.md", "## Step 3: 三\n\n三。\n");
    LessonTextFiles text(dir.path(), kTitles, "ja");
    (void)text.reloadIfChanged();
    EXPECT_NE(text.error().find("lesson.ja.md:1: step 3: the lesson has 2 steps"), std::string::npos)
        << text.error();
    EXPECT_EQ(text.steps()[1].text, "Two.");  // English, with the note
}

// The sections beside the steps are the lesson's own pages, in the language shown: the nth page of
// lesson.ja.md stands for lesson.md's nth, a page it lacks is the English with a note, and neither
// the steps nor the checked exercises are pages.
TEST(LessonTextFiles, PagesBesideTheStepsInTheLanguageShown) {
    fx::test::TempFolder dir;
    write(dir.path() / "lesson.md",
          "# Lesson 99: test\n\nIntro.\n\n## The frame\n\nFrame.\n\n## Step 1: First\n\nOne.\n\n"
          "## Step 2: Second\n\nTwo.\n\n## Pitfalls the chapter warns about\n\n- `glClear`\n\n"
          "## Hard cases and their tests\n\nHard.\n\n## Checked exercise 1: Mine\n\nCheck.\n");
    write(dir.path() / "lesson.ja.md",
          "# レッスン 99：テスト\n\n## フレーム\n\nフレーム。\n\n## ステップ 1: 一つ目\n\n一。\n\n"
          "## ステップ 2: 二つ目\n\n二。\n\n## 章が注意している点\n\n- `glClear` は…\n\n"
          "## 確認課題 1: 自分の\n\n確認。\n");
    LessonTextFiles english(dir.path(), kTitles, "en");
    (void)english.reloadIfChanged();
    ASSERT_TRUE(english.error().empty()) << english.error();
    ASSERT_EQ(english.pages().size(), 3u);
    EXPECT_EQ(english.pages()[0].title, "The frame");
    EXPECT_EQ(english.pages()[1].title, "Pitfalls the chapter warns about");
    EXPECT_EQ(english.pages()[1].text, "- `glClear`");
    EXPECT_EQ(english.pages()[2].title, "Hard cases and their tests");
    for (const auto& page : english.pages()) EXPECT_TRUE(page.note.empty());

    LessonTextFiles japanese(dir.path(), kTitles, "ja");
    (void)japanese.reloadIfChanged();
    ASSERT_TRUE(japanese.error().empty()) << japanese.error();
    ASSERT_EQ(japanese.steps().size(), 2u);
    EXPECT_EQ(japanese.steps()[0].title, "一つ目");
    EXPECT_EQ(japanese.steps()[1].text, "二。");
    ASSERT_EQ(japanese.pages().size(), 3u);
    EXPECT_EQ(japanese.pages()[0].title, "フレーム");
    EXPECT_TRUE(japanese.pages()[0].note.empty());
    EXPECT_EQ(japanese.pages()[1].title, "章が注意している点");
    EXPECT_EQ(japanese.pages()[1].text, "- `glClear` は…");
    EXPECT_EQ(japanese.pages()[2].title, "Hard cases and their tests");
    EXPECT_EQ(japanese.pages()[2].text, "Hard.");
    EXPECT_NE(japanese.pages()[2].note.find("lesson.ja.md"), std::string::npos);
}

TEST(LessonTextFiles, LangOptionIsCheckedOnTheCommandLine) {
    EXPECT_EQ(fx::parseRunOptions({}, 1)->language, "en");
    EXPECT_EQ(fx::parseRunOptions({"--lang", "ja"}, 1)->language, "ja");
    auto bad = fx::parseRunOptions({"--lang", "fr"}, 1);
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.error(), "--lang: expected one of en, ja; got \"fr\"");
}

}  // namespace
