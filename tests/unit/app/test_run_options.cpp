#include <gtest/gtest.h>

#include "app/run_options.hpp"

using fx::parseRunOptions;

TEST(RunOptions, ParsesEveryFlag) {
    auto o = parseRunOptions({"--headless", "--size", "320x180", "--frames", "3", "--step", "2", "--scene", "a.json",
                              "--capture", "out/c", "--capture-float", "--report", "r.json", "--time-step", "0.02",
                              "--seed", "7", "--param", "length=0.5", "--timing", "fenced", "--inspect", "bloom.down[2]",
                              "--overlay", "--list-steps", "--list-params"});
    ASSERT_TRUE(o.ok()) << o.error();
    EXPECT_TRUE(o->forceHeadless);
    EXPECT_EQ(*o->width, 320);
    EXPECT_EQ(*o->height, 180);
    EXPECT_EQ(*o->frames, 3);
    EXPECT_EQ(*o->step, 2);
    EXPECT_EQ(o->scene, "a.json");
    EXPECT_EQ(o->captureDir, "out/c");
    EXPECT_TRUE(o->captureFloat);
    EXPECT_EQ(o->reportFile, "r.json");
    EXPECT_DOUBLE_EQ(*o->timeStep, 0.02);
    EXPECT_EQ(o->seed, 7u);
    ASSERT_EQ(o->params.size(), 1u);
    EXPECT_EQ(o->params[0], "length=0.5");
    EXPECT_EQ(o->timing, fx::TimingMode::Fenced);
    ASSERT_EQ(o->inspect.size(), 1u);
    EXPECT_TRUE(o->overlayHeadless);
    EXPECT_TRUE(o->listSteps);
    EXPECT_TRUE(o->listParams);
}

TEST(RunOptions, ZeroAndOneSizesAreAllowed) {
    EXPECT_EQ(*parseRunOptions({"--size", "0x0"})->width, 0);
    EXPECT_EQ(*parseRunOptions({"--size", "1x1"})->height, 1);
}

struct BadFlag {
    std::vector<std::string> args;
    std::string mustMention;
};

class RunOptionsErrors : public ::testing::TestWithParam<BadFlag> {};

TEST_P(RunOptionsErrors, NameTheFlagAndWhatItTakes) {
    auto o = parseRunOptions(GetParam().args);
    ASSERT_FALSE(o.ok());
    EXPECT_NE(o.error().find(GetParam().mustMention), std::string::npos) << o.error();
}

INSTANTIATE_TEST_SUITE_P(
    All, RunOptionsErrors,
    ::testing::Values(BadFlag{{"--size", "12"}, "--size: expected WxH with sizes from 0 to 16384"},
                      BadFlag{{"--size", "-1x5"}, "--size"}, BadFlag{{"--size", "20000x5"}, "16384"},
                      BadFlag{{"--frames", "0"}, "--frames: expected a frame count from 1"},
                      BadFlag{{"--frames", "two"}, "--frames"}, BadFlag{{"--step", "100"}, "--step: expected a step number from 1 to 99"},
                      BadFlag{{"--time-step", "0"}, "--time-step: expected seconds greater than 0"},
                      BadFlag{{"--time-step", "nan"}, "--time-step"}, BadFlag{{"--seed", "-3"}, "--seed"},
                      BadFlag{{"--param", "novalue"}, "--param: expected name=value"},
                      BadFlag{{"--timing", "maybe"}, "--timing: expected one of gpu, fenced, off"},
                      BadFlag{{"--frames"}, "--frames: needs a value"}, BadFlag{{"--bogus"}, "unknown option \"--bogus\""}));


TEST(RunOptions, GraphTakesTheDotFileToWrite) {
    auto o = parseRunOptions({"--graph", "out/frame.dot"});
    ASSERT_TRUE(o.ok()) << o.error();
    EXPECT_EQ(o->graphFile, "out/frame.dot");
    auto missing = parseRunOptions({"--graph", ""});
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().find("--graph: needs a path"), std::string::npos) << missing.error();
}
