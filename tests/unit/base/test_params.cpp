#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

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
    EXPECT_NE(bad.error().find("parameter length: 2 is out of range; expected a number from 0 to 0.5"),
              std::string::npos)
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

// A choice bound to the enumeration it means: a name sets the enumerator, and a value out of range (a
// preset's index, the bench) is refused, so the lesson reads it without a clamp.
TEST(Params, AChoiceReadsAsItsEnumeration) {
    enum class Curve { clip, reinhard, filmic };
    fx::Choice<Curve> curve{Curve::filmic};
    fx::ParamSet params;
    params.addChoice("curve", &curve, {"clip", "reinhard", "filmic"}, "");
    EXPECT_EQ(*curve, Curve::filmic);
    ASSERT_TRUE(params.assign("curve=reinhard").ok());
    EXPECT_EQ(*curve, Curve::reinhard);
    EXPECT_FALSE(params.assign("curve=3").ok());
    EXPECT_FALSE(params.fromJson(R"({"curve": "-1"})", "p.json").ok());
    EXPECT_EQ(*curve, Curve::reinhard);
    params.find("curve")->set(7);  // the program setting it directly is clamped into range
    EXPECT_EQ(*curve, Curve::filmic);
}

TEST(Params, ATableChoiceReadsAsTheValueItsNameStandsFor) {
    fx::TableChoice<double> scale{{{"half", 0.5}, {"one", 1.0}, {"double", 2.0}}, "one"};
    fx::ParamSet params;
    params.addChoice("scale", &scale, "");
    EXPECT_EQ(params.find("scale")->choices, (std::vector<std::string>{"half", "one", "double"}));
    EXPECT_EQ(*scale, 1.0);
    ASSERT_TRUE(params.assign("scale=double").ok());
    EXPECT_EQ(*scale, 2.0);
    EXPECT_EQ(scale.name(), "double");
    EXPECT_FALSE(params.assign("scale=3").ok());
    EXPECT_EQ(*scale, 2.0);
    params.find("scale")->set(-4);  // the program setting it directly is clamped into range
    EXPECT_EQ(*scale, 0.5);
    params.resetAll();
    EXPECT_EQ(scale.name(), "one");
    EXPECT_THROW((fx::TableChoice<double>{{{"one", 1.0}}, "two"}), std::invalid_argument);
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

// Presets are read by the same strict JSON reader as scenes (issue: duplicate keys and a trailing NUL
// byte were accepted in presets and refused in scenes).
TEST(Params, APresetIsReadAsStrictlyAsAScene) {
    using namespace std::string_literals;
    float a = 1.0f;
    fx::ParamSet params;
    params.addFloat("a", &a, 0.0f, 10.0f, "");
    // The same key twice: JSON readers disagree on which one counts, so neither does.
    auto twice = params.fromJson(R"({"a": "2", "a": "3"})", "p.json");
    ASSERT_FALSE(twice.ok());
    EXPECT_NE(twice.error().find("p.json: a: appears twice"), std::string::npos) << twice.error();
    EXPECT_FLOAT_EQ(a, 1.0f);
    // A NUL byte after the document: a preset is text.
    auto nul = params.fromJson("{\"a\": \"2\"}\0"s, "p.json");
    ASSERT_FALSE(nul.ok());
    EXPECT_NE(nul.error().find("p.json:1:11: JSON syntax error: a NUL byte"), std::string::npos)
        << nul.error();
    EXPECT_FLOAT_EQ(a, 1.0f);
    // Syntax errors carry the line and column, as a scene's do.
    auto syntax = params.fromJson("{\n  \"a\": 2,\n}", "p.json");
    ASSERT_FALSE(syntax.ok());
    EXPECT_NE(syntax.error().find("p.json:3:1: JSON syntax error"), std::string::npos) << syntax.error();
    // A value that is neither text nor a number, and a key the lesson lacks, named in full and escaped.
    auto object = params.fromJson(R"({"a": {"x": 1}})", "p.json");
    ASSERT_FALSE(object.ok());
    EXPECT_NE(object.error().find("p.json: a: expected a number or a string, got an object"),
              std::string::npos)
        << object.error();
    auto unknown = params.fromJson(R"({"x\u0000y": 1})", "p.json");
    ASSERT_FALSE(unknown.ok());
    EXPECT_NE(unknown.error().find("p.json: x\\u0000y: no such parameter"), std::string::npos)
        << unknown.error();
}

TEST(Params, EchoedValuesAreCutAndEscaped) {
    float length = 0.02f;
    fx::ParamSet params;
    params.addFloat("length", &length, 0.0f, 0.5f, "blur length");
    const std::string huge(5000, '7');
    for (const std::string& assignment : {"length=" + huge, huge + "=1", "length=1\n" + huge}) {
        auto refused = params.assign(assignment);
        ASSERT_FALSE(refused.ok());
        EXPECT_LT(refused.error().size(), 300u) << refused.error();
        EXPECT_EQ(refused.error().find('\n'), std::string::npos) << refused.error();
    }
    // The range of a float parameter prints as the float it is, and a refusal near it differs from it.
    auto near = params.assign("length=0.50000001");
    ASSERT_FALSE(near.ok());
    EXPECT_NE(near.error().find("0.50000001 is out of range; expected a number from 0 to 0.5"),
              std::string::npos)
        << near.error();
}

TEST(Params, EveryValueKnowsWhereItCameFrom) {
    float threshold = 1.0f;
    int levels = 6;
    int curve = 2;
    fx::ParamSet params;
    params.addFloat("threshold", &threshold, 0.0f, 16.0f, "").fromScene("postEffects.bloom.threshold");
    params.addInt("levels", &levels, 1, 8, "").fromScene("postEffects.bloom.levels");
    params.addChoice("tone_map", &curve, {"clip", "reinhard", "filmic"}, "")
        .fromScene("postEffects.toneMap.operator");
    const std::vector<std::string> known{"postEffects.bloom.threshold", "postEffects.bloom.levels",
                                         "postEffects.bloom.knee", "postEffects.toneMap.operator"};
    auto source = [&](const char* name) { return fx::toString(params.find(name)->source()); };
    EXPECT_EQ(source("threshold"), "default");

    // The scene first, then a preset, then the command line: each later one overrides.
    std::vector<fx::SettingText> scene{{"postEffects.bloom.threshold", "2.5"},
                                       {"postEffects.bloom.knee", "0.25"},
                                       {"postEffects.toneMap.operator", "reinhard"}};
    ASSERT_TRUE(params.applyScene(scene, known, "class.json").ok());
    EXPECT_FLOAT_EQ(threshold, 2.5f);
    EXPECT_EQ(curve, 1);
    EXPECT_EQ(source("threshold"), "scene");
    EXPECT_EQ(source("tone_map"), "scene");
    EXPECT_EQ(source("levels"), "default");  // the scene has no levels
    // The knee was written (not its default), and the lesson reads the bloom's threshold: a user could
    // have meant it for this lesson. At its default it may never have been written: no word.
    const std::vector<fx::SettingText> defaults{{"postEffects.bloom.knee", "0.5"},
                                                {"postEffects.bloom.levels", "6"}};
    EXPECT_EQ(params.unusedSettings(scene, defaults), std::vector<std::string>{"postEffects.bloom.knee"});
    EXPECT_TRUE(params.unusedSettings({{"postEffects.bloom.knee", "0.5"}}, defaults).empty());
    // A group the lesson reads nothing of (another lesson's effect) is none of its business.
    EXPECT_TRUE(params.unusedSettings({{"postEffects.radialBlur.length", "0.7"}}, defaults).empty());
    ASSERT_TRUE(params.fromJson(R"({"levels": "4"})", "p.json").ok());
    EXPECT_EQ(source("levels"), "preset");
    ASSERT_TRUE(params.assign("threshold=3").ok());
    EXPECT_EQ(source("threshold"), "command line");

    // The program changing a value behind the set's back (a drag in the picture) counts as the overlay,
    // and so does a widget edit once marked.
    params.markStartingValues();
    threshold = 5.0f;
    EXPECT_EQ(source("threshold"), "overlay");
    curve = 0;
    params.markEdited(*params.find("tone_map"));
    EXPECT_EQ(source("tone_map"), "overlay");

    // Reset goes back to how the run started, sources included, not to the lesson's defaults.
    params.resetAll();
    EXPECT_FLOAT_EQ(threshold, 3.0f);
    EXPECT_EQ(source("threshold"), "command line");
    EXPECT_EQ(curve, 1);
    EXPECT_EQ(source("tone_map"), "scene");

    // A temporary change (the bench) is put back with its sources.
    auto saved = params.save();
    params.find("levels")->set(8);
    params.restore(saved);
    EXPECT_EQ(levels, 4);
    EXPECT_EQ(source("levels"), "preset");
}

TEST(Params, SceneValuesOutsideTheRangeAreRefusedByFileFieldAndRange) {
    float intensity = 2.0f;
    float knee = 0.5f;
    fx::ParamSet params;
    params.addFloat("knee", &knee, 0.0f, 1.0f, "").fromScene("postEffects.bloom.knee");
    params.addFloat("intensity", &intensity, 0.0f, 4.0f, "").fromScene("postEffects.bloom.intensity");
    const std::vector<std::string> known{"postEffects.bloom.knee", "postEffects.bloom.intensity"};
    auto bad = params.applyScene({{"postEffects.bloom.knee", "0.25"}, {"postEffects.bloom.intensity", "50"}},
                                 known, "res/scenes/class.json");
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(
        bad.error().find("res/scenes/class.json: postEffects.bloom.intensity: parameter intensity: 50 is out "
                         "of range; expected a number from 0 to 4"),
        std::string::npos)
        << bad.error();
    EXPECT_FLOAT_EQ(knee, 0.5f);  // nothing changed, not even the good setting
    EXPECT_EQ(params.find("knee")->source(), fx::ParamSource::lessonDefault);

    // A lesson that binds a setting scene files do not have is a mistake found at start-up.
    float typo = 0.0f;
    params.addFloat("typo", &typo, 0.0f, 1.0f, "").fromScene("postEffects.blom.knee");
    auto unknown = params.applyScene({}, known, "res/scenes/class.json");
    ASSERT_FALSE(unknown.ok());
    EXPECT_NE(unknown.error().find("\"postEffects.blom.knee\", which scene files do not have"),
              std::string::npos)
        << unknown.error();
}

TEST(Params, AStepListsOnlyItsOwnParameters) {
    // Lesson 04's panel once showed preset=invert during the grayscale step: a parameter says which
    // steps it acts in, and a step lists only those (and the ones for every step).
    int preset = 0, split = 0;
    bool everywhere = false;
    fx::ParamSet params;
    params.addChoice("preset", &preset, {"none", "invert"}, "step 3's matrix").inSteps({2});
    params.addInt("split", &split, 0, 100, "steps 2 and 3").inSteps({1, 2});
    params.addBool("everywhere", &everywhere, "every step");
    auto names = [&](int step) {
        std::vector<std::string> list;
        for (const fx::Param* p : params.forStep(step)) list.push_back(p->name);
        return list;
    };
    EXPECT_EQ(names(0), (std::vector<std::string>{"everywhere"}));
    EXPECT_EQ(names(1), (std::vector<std::string>{"split", "everywhere"}));
    EXPECT_EQ(names(2), (std::vector<std::string>{"preset", "split", "everywhere"}));
    EXPECT_FALSE(params.find("preset")->actsIn(1));
    EXPECT_TRUE(params.find("everywhere")->actsIn(7));
    // A parameter of another step can still be set (a preset file, the command line): it waits.
    EXPECT_TRUE(params.assign("preset=invert").ok());
    EXPECT_EQ(preset, 1);
}

// A parameter whose 0 is a choice ("the step's own count", "off") says so on its slider at 0, and
// shows its number everywhere else; a % in the words is printed as it is.
TEST(Params, ASliderSaysWhatZeroStandsForOnlyAtZero) {
    int lights = 0;
    float blur = 0.0f;
    int plain = 0;
    fx::ParamSet params;
    params.addInt("light_count", &lights, 0, 1024, "lights").showZeroAs("the step's own");
    params.addFloat("blur", &blur, 0.0f, 1.0f, "blur").showZeroAs("off (100% sharp)");
    params.addInt("plain", &plain, 0, 10, "a number");
    EXPECT_EQ(params.find("light_count")->sliderFormat(), "the step's own");
    EXPECT_EQ(params.find("blur")->sliderFormat(), "off (100%% sharp)");
    EXPECT_EQ(params.find("plain")->sliderFormat(), "%d");
    lights = 256;
    blur = 0.005f;
    EXPECT_EQ(params.find("light_count")->sliderFormat(), "%d");
    EXPECT_EQ(params.find("blur")->sliderFormat(), "%.3f");
}

TEST(Params, AStepOpensWithItsOwnValuesAndAChangeStaysWithItsStep) {
    // Lesson 01: broken_shader acts in steps 1 and 2 and starts at syntax_error; the teacher sets it to
    // none in step 1 (as the text says), and step 2 must still open with its own broken shader.
    int broken = 1;
    float exposure = 1.0f;
    int grid = 8;
    fx::ParamSet params;
    params.addChoice("broken_shader", &broken, {"none", "syntax_error"}, "broken").inSteps({0, 1});
    params.addFloat("exposure", &exposure, 0.0f, 4.0f, "every step");
    params.addInt("grid_size", &grid, 1, 64, "step 3").inSteps({2});
    const fx::Param& b = *params.find("broken_shader");  // after the last add: the list may move
    ASSERT_TRUE(params.assign("exposure=2").ok());       // the command line: every step's start
    params.markStartingValues();

    broken = 0;
    params.markEdited(b);
    params.changeStep(0, 1);
    EXPECT_EQ(broken, 1) << "step 2 opens with its own broken shader";
    EXPECT_EQ(b.source(), fx::ParamSource::lessonDefault);
    EXPECT_FLOAT_EQ(exposure, 2.0f) << "a command-line value is every step's";
    params.changeStep(1, 0);
    EXPECT_EQ(broken, 0) << "back in step 1, the change made there";
    EXPECT_EQ(b.source(), fx::ParamSource::overlay);

    // A drag in the picture changes a value without markEdited: it belongs to its step too.
    exposure = 3.0f;
    params.changeStep(0, 1);
    EXPECT_FLOAT_EQ(exposure, 2.0f);
    EXPECT_EQ(params.find("exposure")->source(), fx::ParamSource::commandLine);
    params.changeStep(1, 0);
    EXPECT_FLOAT_EQ(exposure, 3.0f);

    // A change made while another step is shown (the folded "other steps") belongs to the steps the
    // parameter acts in.
    grid = 20;
    params.markEdited(*params.find("grid_size"));
    params.changeStep(0, 2);
    EXPECT_EQ(grid, 20);
    params.changeStep(2, 3);
    EXPECT_EQ(grid, 8);

    // Pinned: kept in every step, then unpinned it is the step's own.
    params.changeStep(3, 0);
    params.setPinned(b, true);
    params.changeStep(0, 1);
    EXPECT_EQ(broken, 0) << "a pinned value is every step's";
    params.setPinned(b, false);
    params.changeStep(1, 4);
    EXPECT_EQ(broken, 1);
    params.changeStep(4, 1);
    EXPECT_EQ(broken, 0) << "unpinned in step 2, the value is step 2's";

    // Reset forgets every step's change and every pin.
    params.setPinned(b, true);
    params.resetAll();
    EXPECT_FALSE(b.pinned);
    params.changeStep(1, 0);
    EXPECT_EQ(broken, 1);
    EXPECT_FLOAT_EQ(exposure, 2.0f);
}

// Issue 40, defect 10: --param threshold=1e-400 was taken as 0 while a scene's 1e-300 is refused.
TEST(Params, ANumberTooSmallForTheFloatIsRefusedNotTakenAsZero) {
    float threshold = 1.0f;
    fx::ParamSet params;
    params.addFloat("threshold", &threshold, 0.0f, 16.0f, "");
    for (const char* text : {"threshold=1e-400", "threshold=1e-300", "threshold=-1e-400"}) {
        auto refused = params.assign(text);
        ASSERT_FALSE(refused.ok()) << text;
        EXPECT_NE(refused.error().find("parameter threshold: "), std::string::npos) << refused.error();
        EXPECT_EQ(threshold, 1.0f) << text;
    }
    EXPECT_NE(params.assign("threshold=1e-400").error().find("too small for a double"), std::string::npos);
    EXPECT_NE(params.assign("threshold=1e-300").error().find("becomes 0 as a float"), std::string::npos);
    EXPECT_TRUE(params.assign("threshold=0").ok());
    EXPECT_TRUE(params.assign("threshold=1e-30").ok());  // small, and a float still
}
