// The exercises in Japanese (app/exercise_words.hpp): every exercise has its words.ja with a Japanese
// title, measure and every hint, and a Japanese locale chooses Japanese.
#include <gtest/gtest.h>

#include <cstdlib>

#include "app/exercise_catalog.hpp"
#include "app/exercise_words.hpp"

namespace fx {
namespace {

bool hasNonAscii(const std::string& text) {
    for (unsigned char c : text) {
        if (c >= 0x80) return true;
    }
    return false;
}

TEST(ExerciseWords, EveryExerciseHasItsJapanese) {
    auto exercises = loadExercises(exerciseRoot());
    ASSERT_TRUE(exercises) << exercises.error();
    ASSERT_FALSE(exercises->empty());
    std::vector<Exercise> english = *exercises;
    Status localised = localiseExercises(*exercises, "ja");
    ASSERT_TRUE(localised) << localised.error();
    for (std::size_t i = 0; i < exercises->size(); ++i) {
        const Exercise& e = (*exercises)[i];
        SCOPED_TRACE(e.id());
        EXPECT_TRUE(hasNonAscii(e.title)) << e.title;
        EXPECT_NE(e.title, english[i].title);
        EXPECT_TRUE(hasNonAscii(e.measures)) << e.measures;
        for (const ExerciseHint& hint : e.hints) EXPECT_TRUE(hasNonAscii(hint.text)) << hint.text;
    }
}

TEST(ExerciseWords, EnglishIsTheExercisesOwnAndAMissingKeyIsAnError) {
    auto exercises = loadExercises(exerciseRoot());
    ASSERT_TRUE(exercises) << exercises.error();
    Exercise e = exercises->front();
    const std::string title = e.title;
    ASSERT_TRUE(localiseExercise(e, "en"));
    EXPECT_EQ(e.title, title);
    e.hints.push_back({"fails", {}, "one hint more than words.ja has"});
    Status missing = localiseExercise(e, "ja");
    ASSERT_FALSE(missing);
    EXPECT_NE(missing.error().find("words.ja"), std::string::npos) << missing.error();
    EXPECT_NE(missing.error().find("hint."), std::string::npos) << missing.error();
}

TEST(ExerciseWords, AJapaneseLocaleSpeaksJapanese) {
    for (const char* name : {"LC_ALL", "LC_MESSAGES", "LANG"}) unsetenv(name);
    EXPECT_EQ(languageFromLocale(), "en");
    setenv("LANG", "ja_JP.UTF-8", 1);
    EXPECT_EQ(languageFromLocale(), "ja");
    setenv("LC_ALL", "C", 1);  // LC_ALL wins over LANG
    EXPECT_EQ(languageFromLocale(), "en");
    unsetenv("LC_ALL");
    unsetenv("LANG");
}

}  // namespace
}  // namespace fx
