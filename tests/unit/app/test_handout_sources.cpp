// The Japanese page lists each section once: a translated part takes its English part's place.
#include <gtest/gtest.h>

#include "app/handout_sources.hpp"

namespace fx::handout {
namespace {

TEST(HandoutSources, ATranslatedPartReplacesItsEnglishOne) {
    EXPECT_EQ(partKey("Checked exercise 1: The planar reflection"), "Checked exercise 1");
    EXPECT_EQ(partKey("Checked exercise 1: 平面反射"), "Checked exercise 1");
    EXPECT_EQ(partKey("Hard cases and their tests"), "Hard cases and their tests");
    EXPECT_EQ(partKey("Tests: what they check"), "Tests: what they check");

    std::vector<Part> parts = {{"Pitfalls the chapter warns about", "en", true},
                               {"Checked exercise 1: The planar reflection", "en", true}};
    replaceOrAdd(parts, {"Checked exercise 1: 平面反射", "ja", false});
    replaceOrAdd(parts, {"落とし穴", "ja", false});
    ASSERT_EQ(parts.size(), 3u);  // lesson 10's page had four: the exercise twice
    EXPECT_EQ(parts[0].heading, "Pitfalls the chapter warns about");
    EXPECT_TRUE(parts[0].englishOnly);
    EXPECT_EQ(parts[1].heading, "Checked exercise 1: 平面反射");
    EXPECT_FALSE(parts[1].englishOnly);
    EXPECT_EQ(parts[2].heading, "落とし穴");
}

}  // namespace
}  // namespace fx::handout
