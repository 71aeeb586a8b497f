// The words files (base/words.hpp): the format's errors, filling, the steps a help names, and every
// lesson's and the app's files in both languages: the same keys, the same placeholders, a Japanese
// label for every parameter and fact the English names.
#include <gtest/gtest.h>

#include <filesystem>

#include "base/paths.hpp"
#include "base/words.hpp"

namespace fx {
namespace {

namespace fs = std::filesystem;

TEST(Words, ParsesKeysTextsAndComments) {
    auto file = parseWords("# a comment\n\nfact.levels = levels (of {asked} asked for)\n", "w.en");
    ASSERT_TRUE(file) << file.error();
    EXPECT_EQ(file->entries.at("fact.levels"), "levels (of {asked} asked for)");
    EXPECT_EQ(fillWords(file->entries.at("fact.levels"), {{"asked", "6"}}), "levels (of 6 asked for)");
}

TEST(Words, RefusesBadLinesNamingTheFileAndLine) {
    auto noSeparator = parseWords("a = b\njust text\n", "lessons/x/words.ja");
    ASSERT_FALSE(noSeparator);
    EXPECT_NE(noSeparator.error().find("lessons/x/words.ja:2:"), std::string::npos) << noSeparator.error();
    EXPECT_FALSE(parseWords("a = b\na = c\n", "w"));  // twice
    EXPECT_FALSE(parseWords("a = {open\n", "w"));     // an unclosed brace
    EXPECT_FALSE(parseWords("a b = text\n", "w"));    // a space in the key
}

TEST(Words, AMissingKeyShowsInBracketsAndIsRemembered) {
    useWords(Words{});
    EXPECT_EQ(say("fact.nowhere"), "[fact.nowhere]");
    bool remembered = false;
    for (const std::string& key : missingWords()) remembered = remembered || key == "fact.nowhere";
    EXPECT_TRUE(remembered);
}

TEST(Words, TheStepsOfAHelpComeFromTheParameter) {
    auto en = Words::loadApp("en");
    ASSERT_TRUE(en) << en.error();
    useWords(std::move(*en));
    EXPECT_EQ(stepsText({4}), "Step 5");
    EXPECT_EQ(stepsText({3, 4}), "Steps 4 and 5");
    EXPECT_EQ(stepsText({2, 3, 4, 5}), "Steps 3 to 6");  // lesson 06's threshold: steps 3 to 6, not 3 to 5
    EXPECT_EQ(stepsText({0, 2, 4}), "Steps 1, 3 and 5");
    auto ja = Words::loadApp("ja");
    ASSERT_TRUE(ja) << ja.error();
    useWords(std::move(*ja));
    EXPECT_EQ(stepsText({2, 3, 4, 5}), "ステップ 3〜6");
}

// Keys only Japanese needs: English shows the parameter's name, a scene setting's help
// (scene/scene_settings.cpp), the key actions, compare modes and the chapters' tables of passes from the
// code (where the frame-order checks read them), and the lesson's title
// from FX_LESSON. (unit.words.<lesson>.<lang> fails on a parameter whose words are missing.)
bool japaneseOnly(const std::string& key) {
    auto ends = [&](std::string_view s) {
        return key.size() >= s.size() && key.compare(key.size() - s.size(), s.size(), s) == 0;
    };
    return ends(".label") || ends(".zero") || ends(".help") || key == "lesson.name" ||
           key.rfind("key.", 0) == 0 || key.rfind("keyName.", 0) == 0 || key.rfind("compareMode.", 0) == 0 ||
           key.rfind("chapter.", 0) == 0;
}

bool hasNonAscii(const std::string& text) {
    for (unsigned char c : text) {
        if (c >= 0x80) return true;
    }
    return false;
}

void compareLanguages(const fs::path& en, const fs::path& ja, bool lesson) {
    SCOPED_TRACE(ja.string());
    auto e = readWords(en);
    auto j = readWords(ja);
    ASSERT_TRUE(e) << e.error();
    ASSERT_TRUE(j) << j.error();
    for (const auto& [key, text] : e->entries) {
        auto it = j->entries.find(key);
        if (it == j->entries.end()) {
            ADD_FAILURE() << key << " has no Japanese in " << ja;
            continue;
        }
        EXPECT_EQ(WordsFile::placeholders(text), WordsFile::placeholders(it->second)) << key;
        if (key.rfind("fact.", 0) == 0 || key.rfind("param.", 0) == 0) {
            EXPECT_TRUE(hasNonAscii(it->second)) << key << " in " << ja << " is not Japanese: " << it->second;
        }
        if (key.rfind("param.", 0) == 0 && key.size() > 5 && key.compare(key.size() - 5, 5, ".help") == 0) {
            const std::string label = key.substr(0, key.size() - 5) + ".label";
            EXPECT_TRUE(j->entries.count(label)) << label << " missing in " << ja;
        }
    }
    for (const auto& [key, text] : j->entries) {
        if (!e->entries.count(key) && !japaneseOnly(key)) ADD_FAILURE() << key << " is in " << ja << " only";
        if (japaneseOnly(key)) {
            EXPECT_TRUE(hasNonAscii(text)) << key << " in " << ja << " is not Japanese: " << text;
        }
    }
    if (lesson) {
        EXPECT_TRUE(j->entries.count("lesson.name")) << "the lesson's Japanese title";
    }
}

TEST(Words, TheAppsWordsHaveBothLanguages) {
    compareLanguages(appWordsFile("en"), appWordsFile("ja"), false);
}

TEST(Words, EveryLessonHasItsWordsInBothLanguages) {
    int lessons = 0;
    for (const fs::directory_entry& folder : fs::directory_iterator(projectRoot() / "lessons")) {
        if (!folder.is_directory()) continue;
        ++lessons;
        compareLanguages(lessonWordsFile(folder.path(), "en"), lessonWordsFile(folder.path(), "ja"), true);
    }
    EXPECT_EQ(lessons, 10);
}

}  // namespace
}  // namespace fx
