// Small helpers behind the loader's messages: byte offset to line and column, and name suggestions.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "base/text_position.hpp"
#include "scene/closest_name.hpp"

namespace {

TEST(TextPosition, CountsLinesAndCharacters) {
    std::string text = "ab\ncd\n\xC3\xA9x";  // "é" is two bytes but one column
    EXPECT_EQ(fx::textPositionOf(text, 0).line, 1u);
    EXPECT_EQ(fx::textPositionOf(text, 0).column, 1u);
    EXPECT_EQ(fx::textPositionOf(text, 4).line, 2u);
    EXPECT_EQ(fx::textPositionOf(text, 4).column, 2u);
    auto afterAccent = fx::textPositionOf(text, 8);  // the 'x'
    EXPECT_EQ(afterAccent.line, 3u);
    EXPECT_EQ(afterAccent.column, 2u);
}

TEST(TextPosition, PastTheEndIsJustAfterTheLastCharacter) {
    auto end = fx::textPositionOf("{\n  \"a\": 1", 1000);
    EXPECT_EQ(end.line, 2u);
    EXPECT_EQ(end.column, 9u);
}

TEST(ClosestName, SuggestsNearNamesOnly) {
    std::vector<std::string> names{"emissive", "emissiveStrength", "baseColor", "baseColorTexture"};
    EXPECT_EQ(fx::closestName("emisive", names).value_or(""), "emissive");
    EXPECT_EQ(fx::closestName("basecolor", names).value_or(""), "baseColor");  // case slip
    EXPECT_EQ(fx::closestName("emsisive", names).value_or(""), "emissive");    // swapped letters
    EXPECT_FALSE(fx::closestName("roughness", names).has_value());
    EXPECT_FALSE(fx::closestName("x", names).has_value());
}

TEST(ClosestName, EditDistanceCountsEachKindOfEdit) {
    EXPECT_EQ(fx::editDistance("fovY", "fovY"), 0u);
    EXPECT_EQ(fx::editDistance("fov", "fovY"), 1u);    // insert
    EXPECT_EQ(fx::editDistance("fovYY", "fovY"), 1u);  // delete
    EXPECT_EQ(fx::editDistance("fovX", "fovY"), 1u);   // substitute
    EXPECT_EQ(fx::editDistance("ofvY", "fovY"), 1u);   // swap
    EXPECT_EQ(fx::editDistance("", "abc"), 3u);
}

}  // namespace
