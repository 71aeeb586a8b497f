#include <gtest/gtest.h>

#include <set>

#include "app/run_options.hpp"
#include "render/frame_report.hpp"

namespace {

// The lessons' step counts differ; these tests use a lesson with five steps.
constexpr int kSteps = 5;

fx::Result<fx::RunOptions> parseRunOptions(const std::vector<std::string>& args) {
    return fx::parseRunOptions(args, kSteps);
}

}  // namespace

TEST(RunOptions, ParsesEveryFlag) {
    auto o = parseRunOptions(
        {"--headless", "--size",       "320x180",       "--frames",  "3",         "--step",
         "2",          "--scene",      "a.json",        "--capture", "out/c",     "--capture-float",
         "--report",   "r.json",       "--time-step",   "0.02",      "--seed",    "7",
         "--param",    "length=0.5",   "--timing",      "fenced",    "--inspect", "bloom.down[2]",
         "--overlay",  "--list-steps", "--list-params", "--lang",    "ja",        "--graph",
         "g.dot"});
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
    EXPECT_EQ(o->inspect[0], "bloom.down[2]");
    EXPECT_TRUE(o->overlayHeadless);
    EXPECT_TRUE(o->listSteps);
    EXPECT_TRUE(o->listParams);
    EXPECT_EQ(o->language, "ja");
    EXPECT_EQ(o->graphFile, "g.dot");
}

TEST(RunOptions, ParsesTheBenchFlags) {
    auto o = parseRunOptions({"--bench", "--knob", "levels", "--bench-frames", "2", "--bench-values", "3",
                              "--bench-out", "out/b", "--preset", "p.json", "--no-overlay", "-h"});
    ASSERT_TRUE(o.ok()) << o.error();
    EXPECT_TRUE(o->bench);
    EXPECT_EQ(o->benchKnob, "levels");
    EXPECT_EQ(o->benchFrames, 2);
    EXPECT_EQ(o->benchValues, 3);
    EXPECT_EQ(o->benchOut, "out/b");
    EXPECT_EQ(o->presetFile, "p.json");
    EXPECT_FALSE(o->overlay);
    EXPECT_TRUE(o->help);
}

TEST(RunOptions, DefaultsWhenNothingIsGiven) {
    auto o = parseRunOptions({});
    ASSERT_TRUE(o.ok()) << o.error();
    EXPECT_EQ(o->language, "en");
    EXPECT_TRUE(o->graphFile.empty());
    EXPECT_FALSE(o->step);
    EXPECT_EQ(o->timing, fx::TimingMode::Automatic);
    EXPECT_TRUE(o->overlay);
    EXPECT_EQ(o->seed, 1u);
}

TEST(RunOptions, StepRangeIsTheLessons) {
    EXPECT_EQ(*fx::parseRunOptions({"--step", "5"}, 5)->step, 5);
    EXPECT_EQ(*fx::parseRunOptions({"--step", "1"}, 1)->step, 1);
    for (const char* bad : {"0", "6", "-1"}) {
        auto o = fx::parseRunOptions({"--step", bad}, 5);
        ASSERT_FALSE(o.ok()) << bad;
        EXPECT_EQ(o.error(), std::string("--step: expected a step number from 1 to 5, got \"") + bad + "\"");
    }
    auto twelve = fx::parseRunOptions({"--step", "13"}, 12);
    ASSERT_FALSE(twelve.ok());
    EXPECT_NE(twelve.error().find("from 1 to 12"), std::string::npos) << twelve.error();
}

TEST(RunOptions, ParamAndInspectMayRepeat) {
    auto o = parseRunOptions({"--param", "a=1", "--inspect", "x", "--param", "b=2", "--inspect", "y"});
    ASSERT_TRUE(o.ok()) << o.error();
    EXPECT_EQ(o->params, (std::vector<std::string>{"a=1", "b=2"}));
    EXPECT_EQ(o->inspect, (std::vector<std::string>{"x", "y"}));
}

TEST(RunOptions, ASwitchGivenTwiceIsHarmless) {
    auto o = parseRunOptions({"--headless", "--headless"});
    ASSERT_TRUE(o.ok()) << o.error();
    EXPECT_TRUE(o->forceHeadless);
}

TEST(RunOptions, ASingleValuedFlagGivenTwiceIsAnError) {
    const std::vector<std::pair<std::string, std::string>> flagsWithAValue = {
        {"--scene", "a.json"}, {"--size", "4x4"},      {"--frames", "2"},       {"--step", "2"},
        {"--lang", "en"},      {"--graph", "g.dot"},   {"--timing", "off"},     {"--seed", "2"},
        {"--capture", "c"},    {"--report", "r.json"}, {"--preset", "p.json"},  {"--time-step", "0.5"},
        {"--knob", "k"},       {"--bench-out", "b"},   {"--bench-frames", "2"}, {"--bench-values", "2"}};
    for (const auto& [flag, value] : flagsWithAValue) {
        auto once = parseRunOptions({flag, value});
        ASSERT_TRUE(once.ok()) << flag << ": " << once.error();
        auto twice = parseRunOptions({flag, value, "--headless", flag, value});
        ASSERT_FALSE(twice.ok()) << flag;
        EXPECT_EQ(twice.error(), flag + ": given more than once (again as \"" + value + "\"); give it once");
    }
}

TEST(RunOptions, AnUnknownFlagGetsTheNearestName) {
    auto o = parseRunOptions({"--scnee", "a.json"});
    ASSERT_FALSE(o.ok());
    EXPECT_NE(o.error().find("unknown option \"--scnee\"; did you mean --scene? (see --help)"),
              std::string::npos)
        << o.error();
    auto far = parseRunOptions({"--completely-different"});
    ASSERT_FALSE(far.ok());
    EXPECT_EQ(far.error().find("did you mean"), std::string::npos) << far.error();
}

TEST(RunOptions, HelpListsEveryFlagAndTheWindowKeys) {
    std::string help = fx::runOptionsHelp("fxlab-99-test");
    EXPECT_EQ(help.rfind("usage: fxlab-99-test [options]", 0), 0u);
    for (const char* line :
         {"--size WxH", "--lang en|ja", "--graph FILE.dot", "--param NAME=VALUE", "--help, -h",
          "--bench-values N", "--inspect NAME", "--no-overlay", "--time-step S"}) {
        EXPECT_NE(help.find(std::string("\n  ") + line + " "), std::string::npos) << line << " in\n" << help;
    }
    for (const char* key : {"left arrow", "right arrow", "F1", "F5", "F12", "Esc"}) {
        EXPECT_NE(help.find(std::string("\n  ") + key + " "), std::string::npos) << key << " in\n" << help;
    }
    // The help's flags are exactly these, and each of them parses (or asks for its value).
    std::set<std::string> inHelp;
    for (std::size_t at = 0; (at = help.find("\n  --", at)) != std::string::npos; ++at) {
        std::size_t start = at + 3;
        std::string flag = help.substr(start, help.find_first_of(" ,", start) - start);
        inHelp.insert(flag);
        // --all-steps goes with --capture DIR (AllStepsNeedsACaptureFolder).
        // --renderdoc-open goes with --renderdoc FILE.rdc (RenderDocFlags).
        auto o = flag == "--all-steps"        ? parseRunOptions({flag, "--capture", "c"})
                 : flag == "--renderdoc-open" ? parseRunOptions({flag, "--renderdoc", "c.rdc"})
                                              : parseRunOptions({flag});
        EXPECT_TRUE(o.ok() || o.error().rfind(flag + ": needs a value (", 0) == 0)
            << flag << ": " << (o.ok() ? "" : o.error());
    }
    EXPECT_EQ(inHelp,
              (std::set<std::string>{
                  "--headless",      "--size",         "--frames",          "--step",          "--exercise",
                  "--scene",         "--lang",         "--param",           "--preset",        "--capture",
                  "--capture-float", "--report",       "--graph",           "--time-step",     "--seed",
                  "--timing",        "--inspect",      "--overlay",         "--no-overlay",    "--bench",
                  "--knob",          "--bench-frames", "--bench-values",    "--bench-out",     "--list-steps",
                  "--list-params",   "--help",         "--press",           "--all-steps",     "--resize",
                  "--picture-scale", "--aspect",       "--min-frame-time",  "--resource-log",  "--cost",
                  "--dump-shaders",  "--renderdoc",    "--renderdoc-frame", "--renderdoc-open"}));
}

TEST(RunOptions, PictureScaleAspectAndASlowRendererImitated) {
    auto o = parseRunOptions({"--picture-scale", "40%", "--aspect", "4:3", "--min-frame-time", "150"});
    ASSERT_TRUE(o.ok()) << o.error();
    EXPECT_DOUBLE_EQ(*o->pictureScale, 0.4);
    EXPECT_DOUBLE_EQ(o->aspect, 4.0 / 3.0);
    EXPECT_EQ(o->minFrameMs, 150);
    // The defaults: automatic, 16:9, no wait.
    o = parseRunOptions({});
    EXPECT_FALSE(o->pictureScale.has_value());
    EXPECT_DOUBLE_EQ(o->aspect, 16.0 / 9.0);
    EXPECT_EQ(o->minFrameMs, 0);
    o = parseRunOptions({"--picture-scale", "0.25", "--aspect", "free"});
    EXPECT_DOUBLE_EQ(*o->pictureScale, 0.25);
    EXPECT_EQ(o->aspect, 0.0);
    EXPECT_DOUBLE_EQ(parseRunOptions({"--aspect", "1.85"})->aspect, 1.85);
    EXPECT_FALSE(parseRunOptions({"--picture-scale", "auto"})->pictureScale.has_value());
}

fx::FrameReport reportWithTextures(std::vector<std::string> names) {
    fx::FrameReport report;
    for (auto& n : names)
        report.textures.push_back(fx::TextureRecord{n, {}, {}, 0, {}, false, {}, false, false});
    return report;
}

TEST(RunOptions, InspectNamesTheFrameHasGetNoWarning) {
    auto report = reportWithTextures({"scene.hdr", "bloom.down[0]", "bloom.down[1]"});
    EXPECT_TRUE(fx::unknownInspectWarnings({"bloom.down[1]", "scene.hdr"}, report, 0).empty());
    EXPECT_TRUE(fx::unknownInspectWarnings({}, report, 0).empty());
}

TEST(RunOptions, AnUnknownInspectNameIsNamedWithTheNearestNames) {
    auto report = reportWithTextures(
        {"scene.hdr", "bloom.down[0]", "bloom.down[1]", "bloom.up[0]", "shadow.depth", "ldr", "tonemapped"});
    auto warnings = fx::unknownInspectWarnings({"bloom.dwn[1]", "scene.hdr", "zzz"}, report, 3);
    ASSERT_EQ(warnings.size(), 2u);
    const std::string& typo = warnings[0];
    EXPECT_NE(typo.find("step 4's frame has no texture named \"bloom.dwn[1]\""), std::string::npos) << typo;
    EXPECT_NE(typo.find("did you mean \"bloom.down[1]\"?"), std::string::npos) << typo;
    EXPECT_NE(typo.find("nearest names it has: bloom.down[1], bloom.down[0]"), std::string::npos) << typo;
    EXPECT_EQ(typo.find("tonemapped"), std::string::npos) << "at most five names: " << typo;
    const std::string& far = warnings[1];
    EXPECT_NE(far.find("\"zzz\""), std::string::npos) << far;
    EXPECT_EQ(far.find("did you mean"), std::string::npos) << far;
    EXPECT_NE(far.find("nearest names it has: "), std::string::npos) << far;
}

TEST(RunOptions, AnInspectNameOnAFrameWithoutTexturesSaysSo) {
    auto warnings = fx::unknownInspectWarnings({"x"}, fx::FrameReport{}, 0);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("it has no textures"), std::string::npos) << warnings[0];
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
    ::testing::Values(
        BadFlag{{"--size", "12"}, "--size: expected WxH with sizes from 0 to 16384"},
        BadFlag{{"--size", "-1x5"}, "--size"}, BadFlag{{"--size", "20000x5"}, "16384"},
        BadFlag{{"--frames", "0"}, "--frames: expected a frame count from 1"},
        BadFlag{{"--frames", "two"}, "--frames"},
        BadFlag{{"--step", "6"}, "--step: expected a step number from 1 to 5"},
        BadFlag{{"--step", "0"}, "--step: expected a step number from 1 to 5"},
        BadFlag{{"--lang", "fr"}, "--lang: expected one of en, ja; got \"fr\""},
        BadFlag{{"--graph", ""}, "--graph: needs a path"}, BadFlag{{"--scene", ""}, "--scene: needs a path"},
        BadFlag{{"--inspect", ""}, "--inspect: needs a texture name"},
        BadFlag{{"--bench-frames", "0"}, "--bench-frames: expected a frame count from 1 to 1000"},
        BadFlag{{"--time-step", "0"}, "--time-step: expected seconds greater than 0"},
        BadFlag{{"--time-step", "nan"}, "--time-step"},
        BadFlag{{"--picture-scale", "0.05"}, "--picture-scale: expected auto, or a share"},
        BadFlag{{"--picture-scale", "150%"}, "--picture-scale"},
        BadFlag{{"--picture-scale", "half"}, "--picture-scale"},
        BadFlag{{"--aspect", "16:0"}, "--aspect: expected W:H"}, BadFlag{{"--aspect", "wide"}, "--aspect"},
        BadFlag{{"--aspect", "0.01"}, "--aspect"},
        BadFlag{{"--min-frame-time", "-5"}, "--min-frame-time: expected milliseconds"},
        BadFlag{{"--seed", "-3"}, "--seed"}, BadFlag{{"--param", "novalue"}, "--param: expected name=value"},
        BadFlag{{"--timing", "maybe"}, "--timing: expected one of gpu, fenced, off"},
        BadFlag{{"--cost", "money"}, "--cost: expected one of time, traffic; got \"money\""},
        BadFlag{{"--dump-shaders", ""}, "--dump-shaders: needs a path"},
        BadFlag{{"--frames"}, "--frames: needs a value"},
        BadFlag{{"--bogus"}, "unknown option \"--bogus\""}));

TEST(RunOptions, GraphTakesTheDotFileToWrite) {
    auto o = parseRunOptions({"--graph", "out/frame.dot"});
    ASSERT_TRUE(o.ok()) << o.error();
    EXPECT_EQ(o->graphFile, "out/frame.dot");
    auto missing = parseRunOptions({"--graph", ""});
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().find("--graph: needs a path"), std::string::npos) << missing.error();
}

TEST(RunOptions, DumpShadersTakesAFolderAndCostAnAxis) {
    auto o = parseRunOptions({"--dump-shaders", "out/shaders", "--bench", "--cost", "traffic"});
    ASSERT_TRUE(o.ok()) << o.error();
    EXPECT_EQ(o->shaderDump, "out/shaders");
    EXPECT_EQ(o->benchCost, fx::BenchCost::traffic);
    auto plain = parseRunOptions({"--bench"});
    ASSERT_TRUE(plain.ok()) << plain.error();
    EXPECT_TRUE(plain->shaderDump.empty());
    EXPECT_EQ(plain->benchCost, fx::BenchCost::time);
}

TEST(RunOptions, PressNamesAWindowKeyAndAFrame) {
    auto o = parseRunOptions({"--press", "space@3", "--press", "F2"});
    ASSERT_TRUE(o) << o.error();
    ASSERT_EQ(o->presses.size(), 2u);
    EXPECT_EQ(o->presses[0].frame, 3);
    EXPECT_TRUE(o->presses[0].press.pause);
    EXPECT_EQ(o->presses[1].frame, 0);
    EXPECT_TRUE(o->presses[1].press.resetLayout);
    auto typo = parseRunOptions({"--press", "spcae"});
    ASSERT_FALSE(typo);
    EXPECT_NE(typo.error().find("--press: no key named \"spcae\" (did you mean space?)"), std::string::npos)
        << typo.error();
    EXPECT_FALSE(parseRunOptions({"--press", "F2@x"}));
}

TEST(RunOptions, ResizeTakesASizeAndAFrame) {
    auto o = parseRunOptions({"--resize", "400x300@2", "--resize", "1280x720@4"});
    ASSERT_TRUE(o) << o.error();
    ASSERT_EQ(o->resizes.size(), 2u);
    EXPECT_EQ(o->resizes[0].width, 400);
    EXPECT_EQ(o->resizes[1].frame, 4);
    EXPECT_FALSE(parseRunOptions({"--resize", "400x300"}));
}

TEST(RunOptions, AllStepsNeedsACaptureFolder) {
    auto alone = parseRunOptions({"--all-steps"});
    ASSERT_FALSE(alone);
    EXPECT_EQ(alone.error(), "--all-steps: needs --capture DIR (each step's captures go into DIR/step-K/)");
    EXPECT_TRUE(parseRunOptions({"--all-steps", "--capture", "slides"})->allSteps);
    EXPECT_FALSE(parseRunOptions({"--all-steps", "--capture", "slides", "--step", "2"}));
}

TEST(RunOptions, HelpListsEveryKeyOfTheWindow) {
    const std::string help = fx::runOptionsHelp("fxlab-05-radial-blur");
    for (const fx::WindowKeyHelp& k : fx::windowKeysHelp()) {
        EXPECT_NE(help.find(k.action), std::string::npos) << k.key;
        EXPECT_NE(help.find("[" + k.token + "]"), std::string::npos) << k.key;
        // Every key a press can name.
        EXPECT_TRUE(fx::keyPressNamed(k.token)) << k.token;
    }
    for (const char* key : {"space", "Page Down", "F3", "F4", "+", "F2", "F12"})
        EXPECT_NE(help.find(std::string("\n  ") + key), std::string::npos) << key;
}

// A value the user typed is echoed cut to a readable length, its control characters escaped (issue: a
// 5,000-character --inspect name printed 5,390 bytes).
TEST(RunOptions, EchoedValuesAreCutAndEscaped) {
    const std::string huge(5000, 'n');
    auto report = reportWithTextures({"scene.hdr"});
    auto warnings = fx::unknownInspectWarnings({huge}, report, 0);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_LT(warnings[0].size(), 300u) << warnings[0];
    EXPECT_NE(warnings[0].find("... (5000 bytes)"), std::string::npos) << warnings[0];
    // Every flag that echoes its value does the same.
    for (const char* flag : {"--size", "--frames", "--lang", "--timing", "--time-step", "--param", "--press",
                             "--resize", "--step"}) {
        auto refused = parseRunOptions({flag, huge});
        ASSERT_FALSE(refused.ok()) << flag;
        EXPECT_LT(refused.error().size(), 300u) << flag << ": " << refused.error();
    }
    auto unknown = parseRunOptions({"--" + huge});
    ASSERT_FALSE(unknown.ok());
    EXPECT_LT(unknown.error().size(), 300u) << unknown.error();
    auto twice = parseRunOptions({"--scene", "a.json", "--scene", huge});
    ASSERT_FALSE(twice.ok());
    EXPECT_LT(twice.error().size(), 300u) << twice.error();
    // A newline or an escape sequence cannot start a new line or recolour the terminal.
    auto control = parseRunOptions({"--size", "1x1\n\x1b[2J"});
    ASSERT_FALSE(control.ok());
    EXPECT_NE(control.error().find("1x1\\n\\u001b[2J"), std::string::npos) << control.error();
}

TEST(RunOptions, RenderDocFlags) {
    auto o = parseRunOptions({"--renderdoc", "out/06.rdc", "--renderdoc-frame", "2", "--renderdoc-open"});
    ASSERT_TRUE(o.ok()) << o.error();
    EXPECT_EQ(o->renderdoc, "out/06.rdc");
    EXPECT_EQ(*o->renderdocFrame, 2);
    EXPECT_TRUE(o->renderdocOpen);
    EXPECT_FALSE(parseRunOptions({}).value().renderdocFrame);
    // What RenderDoc's tools open, and nothing that would be silently ignored.
    auto error = [](std::vector<std::string> args) {
        auto parsed = parseRunOptions(args);
        return parsed ? std::string() : parsed.error();
    };
    EXPECT_NE(error({"--renderdoc", "out/06.png"}).find("--renderdoc: expected a file name ending in .rdc"),
              std::string::npos);
    EXPECT_NE(error({"--renderdoc", ".rdc"}).find("ending in .rdc"), std::string::npos);
    EXPECT_NE(error({"--renderdoc-frame", "2"}).find("--renderdoc-frame: needs --renderdoc FILE.rdc"),
              std::string::npos);
    EXPECT_NE(error({"--renderdoc-open"}).find("--renderdoc-open: needs --renderdoc"), std::string::npos);
    EXPECT_NE(error({"--renderdoc", "a.rdc", "--renderdoc-frame", "0"}).find("from 1 to"), std::string::npos);
    EXPECT_NE(error({"--renderdoc", "a.rdc", "--frames", "3", "--renderdoc-frame", "4"})
                  .find("--renderdoc-frame: frame 4 of a run of 3 frames"),
              std::string::npos);
    EXPECT_NE(error({"--renderdoc", "a.rdc", "--bench"}).find("leave out --bench"), std::string::npos);
    // The window's key, in --help and the Keys tab, and not F12 (fxlab's screenshot).
    const std::string help = fx::runOptionsHelp("fxlab-06-bloom");
    EXPECT_NE(help.find("\n  F9 [F9]"), std::string::npos) << help;
    EXPECT_NE(help.find("RenderDoc"), std::string::npos);
    EXPECT_TRUE(fx::keyPressNamed("F9").value().renderdoc);
    EXPECT_FALSE(fx::keyPressNamed("F12").value().renderdoc);
}
