// How messages show numbers and a user's text (issue: refusals that contradicted themselves, a NUL that
// cut a warning short, a 5,000-character name echoed whole).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "base/message_text.hpp"

TEST(MessageText, NumbersPrintInTheirShortestExactForm) {
    // Six significant digits made 179.99999999 read as 180 and 2147483648 as 2.14748e+09.
    EXPECT_EQ(fx::formatNumber(179.99999999), "179.99999999");
    EXPECT_EQ(fx::formatNumber(180.0f), "180");
    EXPECT_EQ(fx::formatNumber(2147483648.0), "2147483648");
    EXPECT_EQ(fx::formatNumber(2147483647.0), "2147483647");
    EXPECT_EQ(fx::formatNumber(0.1f), "0.1");
    EXPECT_EQ(fx::formatNumber(0.1), "0.1");
    EXPECT_EQ(fx::formatNumber(100000.0), "100000");
    EXPECT_EQ(fx::formatNumber(0.00025), "0.00025");
    EXPECT_EQ(fx::formatNumber(1e30), "1e+30");
    EXPECT_EQ(fx::formatNumber(1e-300), "1e-300");
    EXPECT_EQ(fx::formatNumber(-3), "-3");
    // Two numbers that differ never print alike.
    EXPECT_NE(fx::formatNumber(1.0000001), fx::formatNumber(1.0));
    EXPECT_NE(fx::formatNumber(std::nextafter(180.0f, 0.0f)), fx::formatNumber(180.0f));
}

TEST(MessageText, ControlCharactersAreEscapedSoNothingCutsTheLine) {
    using namespace std::string_literals;
    EXPECT_EQ(fx::excerpt("vers\0ion"s), "vers\\u0000ion");
    EXPECT_EQ(fx::excerpt("a\nb\tc\x1b[31m"), "a\\nb\\tc\\u001b[31m");
    EXPECT_EQ(fx::excerpt("名前"), "名前");  // UTF-8 stays as it is
}

TEST(MessageText, LongTextIsCutWithItsLength) {
    std::string name(5000, 'n');
    std::string shown = fx::excerpt(name);
    EXPECT_LT(shown.size(), 80u) << shown;
    EXPECT_NE(shown.find("... (5000 bytes)"), std::string::npos) << shown;
    // Cut at a character boundary: no half of a three-byte character.
    std::string japanese;
    for (int i = 0; i < 40; ++i) japanese += "名";
    std::string cut = fx::excerpt(japanese);
    EXPECT_EQ(cut.substr(0, cut.find("...")).size() % 3, 0u) << cut;
}
