// Any byte in a name (issue 40, defect 3): JSON with a string or a key that is not UTF-8 is written with
// those bytes escaped, never an abort (nlohmann::json throws type_error.316 on them).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "base/json_text.hpp"

using namespace std::string_literals;

TEST(JsonText, BytesThatAreNotUtf8AreWrittenEscaped) {
    nlohmann::json j = {{"scene", "sc\xff.json"},
                        {"list",
                         {"ok",
                          "st\xff"
                          "udent"}},
                        {"k\xfe", 1}};
    EXPECT_THROW((void)j.dump(), nlohmann::json::type_error);  // what aborted the lessons before
    const std::string text = fx::dumpJson(j);
    EXPECT_EQ(nlohmann::json::parse(text)["scene"], "sc\\xff.json");
    EXPECT_EQ(nlohmann::json::parse(text)["list"][1], "st\\xffudent");
    EXPECT_TRUE(nlohmann::json::parse(text).contains("k\\xfe"));
    nlohmann::ordered_json o = {{"student",
                                 "st\xff"
                                 "udent"}};
    EXPECT_EQ(fx::dumpJson(o, 2), "{\n  \"student\": \"st\\\\xffudent\"\n}");
}

TEST(JsonText, WellFormedTextIsLeftAsItIs) {
    nlohmann::json j = {{"name", "名前 ✓"}, {"n", 1.5}};
    EXPECT_EQ(fx::dumpJson(j, 2), j.dump(2));
    EXPECT_EQ(fx::utf8Escaped("名前"), "名前");
}

TEST(JsonText, EveryMalformedShapeIsEscapedByteByByte) {
    EXPECT_EQ(fx::utf8Escaped("\xc0\xaf"), "\\xc0\\xaf");                    // an overlong '/'
    EXPECT_EQ(fx::utf8Escaped("\xed\xa0\x80"), "\\xed\\xa0\\x80");           // a surrogate
    EXPECT_EQ(fx::utf8Escaped("a\xe3\x81"), "a\\xe3\\x81");                  // cut short at the end
    EXPECT_EQ(fx::utf8Escaped("\xf4\x90\x80\x80"), "\\xf4\\x90\\x80\\x80");  // past U+10FFFF
    EXPECT_EQ(fx::utf8Escaped("\x80z"), "\\x80z");
    EXPECT_FALSE(fx::isValidUtf8("\xff"));
    EXPECT_TRUE(fx::isValidUtf8("\xf0\x9f\x98\x80"));
    EXPECT_TRUE(fx::isValidUtf8(""s));
}
