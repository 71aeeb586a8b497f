// What the handout takes from a lesson's text: the parts beside the steps, in the page's language.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "app/handout_sources.hpp"
#include "base/paths.hpp"

namespace {

namespace fs = std::filesystem;
using fx::handout::Part;
using fx::handout::translatedParts;

// The translation's nth part stands for lesson.md's nth; what it lacks stays English, marked so.
TEST(HandoutSources, TranslatedPartsReplaceTheEnglishOnesInOrder) {
    const std::vector<Part> english{{"The frame", "Frame.", false},
                                    {"Pitfalls the chapter warns about", "Pitfalls.", false},
                                    {"Hard cases and their tests", "Hard.", false}};
    const std::vector<Part> japanese{{"フレーム", "フレーム。", false},
                                     {"章が注意している点", "注意点。", false}};
    const auto some = translatedParts(english, japanese);
    ASSERT_EQ(some.size(), 3u);
    EXPECT_EQ(some[0].heading, "フレーム");
    EXPECT_FALSE(some[0].englishOnly);
    EXPECT_EQ(some[1].text, "注意点。");
    EXPECT_FALSE(some[1].englishOnly);
    EXPECT_EQ(some[2].heading, "Hard cases and their tests");
    EXPECT_TRUE(some[2].englishOnly);

    const std::vector<Part> all{japanese[0], japanese[1], {"難しいケースとそのテスト", "難しい。", false}};
    for (const Part& p : translatedParts(english, all)) EXPECT_FALSE(p.englishOnly) << p.heading;
    const auto none = translatedParts(english, {});
    ASSERT_EQ(none.size(), 3u);
    for (const Part& p : none) EXPECT_TRUE(p.englishOnly) << p.heading;
}

// Every lesson.ja.md gives every section of its lesson.md: no Japanese handout has an English-only
// part, and each part is headed in Japanese (not a copied English heading).
TEST(HandoutSources, JapaneseHandoutsHaveNoEnglishOnlyPart) {
    int lessons = 0;
    for (const auto& entry : fs::directory_iterator(fx::projectRoot() / "lessons")) {
        const fs::path folder = entry.path();
        if (!fs::is_regular_file(folder / "lesson.ja.md")) continue;
        ++lessons;
        SCOPED_TRACE(folder.filename().string());
        auto english = fx::handout::readLessonText(folder / "lesson.md");
        auto japanese = fx::handout::readLessonText(folder / "lesson.ja.md");
        ASSERT_TRUE(english.ok()) << english.error();
        ASSERT_TRUE(japanese.ok()) << japanese.error();
        for (const auto& [en, ja] :
             {std::pair{&english->before, &japanese->before}, {&english->after, &japanese->after}}) {
            EXPECT_EQ(ja->size(), en->size()) << "lesson.ja.md has another number of sections than lesson.md";
            for (const Part& p : translatedParts(*en, *ja)) {
                EXPECT_FALSE(p.englishOnly) << p.heading;
                bool japaneseHeading = false;
                for (char c : p.heading)
                    japaneseHeading = japaneseHeading || static_cast<unsigned char>(c) >= 0x80;
                EXPECT_TRUE(japaneseHeading) << p.heading;
            }
        }
        EXPECT_FALSE(japanese->intro.empty());
    }
    EXPECT_EQ(lessons, 10);
}

}  // namespace
