#include <gtest/gtest.h>

#include "base/params.hpp"

TEST(Params, ChecksTypeAndRangeAndKeepsTheOldValue) {
    float length = 0.02f;
    int samples = 8;
    bool on = false;
    int preset = 0;
    fx::ParamSet params;
    params.addFloat("length", &length, 0.0f, 0.5f, "blur length");
    params.addInt("samples", &samples, 1, 64, "taps");
    params.addBool("enabled", &on, "on or off");
    params.addChoice("preset", &preset, {"none", "grayscale", "sepia"}, "matrix");

    EXPECT_TRUE(params.assign("length=0.25").ok());
    EXPECT_FLOAT_EQ(length, 0.25f);
    auto bad = params.assign("length=2");
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error().find("parameter length: 2 is out of range; expected a number from 0 to 0.5"), std::string::npos)
        << bad.error();
    EXPECT_FLOAT_EQ(length, 0.25f);

    EXPECT_FALSE(params.assign("samples=3.5").ok());
    EXPECT_FALSE(params.assign("samples=nan").ok());
    EXPECT_TRUE(params.assign("samples=64").ok());
    EXPECT_EQ(samples, 64);
    EXPECT_TRUE(params.assign("enabled=true").ok());
    EXPECT_TRUE(on);
    auto choice = params.assign("preset=purple");
    ASSERT_FALSE(choice.ok());
    EXPECT_NE(choice.error().find("one of: none, grayscale, sepia"), std::string::npos);
    EXPECT_TRUE(params.assign("preset=sepia").ok());
    EXPECT_EQ(preset, 2);
    auto unknown = params.assign("lenght=1");
    ASSERT_FALSE(unknown.ok());
    EXPECT_NE(unknown.error().find("this lesson has: length, samples, enabled, preset"), std::string::npos);

    params.resetAll();
    EXPECT_FLOAT_EQ(length, 0.02f);
    EXPECT_EQ(samples, 8);
}

TEST(Params, PresetRoundTripAndAllOrNothingLoad) {
    float a = 1.0f;
    int c = 0;
    fx::ParamSet params;
    params.addFloat("a", &a, 0.0f, 10.0f, "");
    params.addChoice("c", &c, {"x", "y"}, "");
    a = 3.5f;
    c = 1;
    std::string saved = params.toJson();
    params.resetAll();
    ASSERT_TRUE(params.fromJson(saved, "preset.json").ok());
    EXPECT_FLOAT_EQ(a, 3.5f);
    EXPECT_EQ(c, 1);
    auto bad = params.fromJson(R"({"a": "4", "c": "z"})", "preset.json");
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error().find("preset.json: c:"), std::string::npos) << bad.error();
    EXPECT_FLOAT_EQ(a, 3.5f);  // nothing changed
}
