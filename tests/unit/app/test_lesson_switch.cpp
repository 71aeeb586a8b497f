// Page Down / Page Up start the neighbouring lesson's executable with the flags that mean the same to
// every lesson; --all-steps runs one step per child with its own capture folder.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "app/lesson_switch.hpp"

namespace fs = std::filesystem;
using Args = std::vector<std::string>;

// A program's file name on this system: Windows runs .exe's; POSIX runs files with the exec bit.
#ifdef _WIN32
const std::string kExe = ".exe";
#else
const std::string kExe;
#endif

TEST(LessonSwitch, TheNeighboursAreTheLessonExecutablesInNumberOrder) {
    const fs::path dir = fs::temp_directory_path() / "fxlab-lesson-switch-test";
    fs::remove_all(dir);
    fs::create_directories(dir);
    for (const std::string& name : {"fxlab-02-b" + kExe, "fxlab-01-a" + kExe, "fxlab-10-c" + kExe,
                                    std::string("fxlab-notes.txt"), std::string("fxlab-03-d.log")}) {
        std::ofstream(dir / name) << "x";
        fs::permissions(dir / name, fs::perms::owner_all);
    }
    fs::permissions(dir / "fxlab-03-d.log", fs::perms::owner_read);  // not executable
    auto found = fx::lessonExecutables(dir);
    ASSERT_EQ(found.size(), 3u);
    EXPECT_EQ(found[0].filename(), "fxlab-01-a" + kExe);
    EXPECT_EQ(found[2].filename(), "fxlab-10-c" + kExe);
    // The neighbour is found by the lesson's name, without the system's suffix.
    EXPECT_EQ(fx::neighbourIn(found, "fxlab-01-a", 1)->filename(), "fxlab-02-b" + kExe);
    EXPECT_EQ(fx::neighbourIn(found, "fxlab-02-b", -1)->filename(), "fxlab-01-a" + kExe);
    EXPECT_FALSE(fx::neighbourIn(found, "fxlab-10-c", 1));
    EXPECT_FALSE(fx::neighbourIn(found, "fxlab-01-a", -1));
    EXPECT_FALSE(fx::neighbourIn(found, "fxlab-99-unknown", 1));
    fs::remove_all(dir);
}

TEST(LessonSwitch, TheNextLessonKeepsTheCommonFlagsAndTheWindowSize) {
    Args args = {"--step",     "3",        "--scene", "s.json",       "--param",   "a=1",           "--lang",
                 "ja",         "--size",   "800x600", "--no-overlay", "--inspect", "bloom.down[0]", "--press",
                 "pagedown@2", "--frames", "9"};
    EXPECT_EQ(fx::neighbourArguments(args, {1024, 768}),
              (Args{"--lang", "ja", "--no-overlay", "--frames", "9", "--size", "1024x768"}));
}

TEST(LessonSwitch, EachStepOfAllStepsHasItsOwnFolder) {
    Args args = {"--all-steps", "--capture", "slides",  "--size", "640x360",
                 "--report",    "r.json",    "--graph", "g.dot"};
    EXPECT_EQ(fx::stepCaptureArguments(args, "slides", 2),
              (Args{"--headless", "--size", "640x360", "--step", "2", "--capture", "slides/step-2",
                    "--report", "slides/step-2/report.json", "--graph", "slides/step-2/graph.dot"}));
}
