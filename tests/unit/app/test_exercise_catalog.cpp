// The exercises' data and the student's side of them, without GL: every shipped exercise loads, a
// bad exercise.json names its file and field, start copies a starter and never overwrites work, the
// progress file round-trips, and the watchdog ends a child that does not finish.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <fstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "app/child_watchdog.hpp"
#include "app/exercise_catalog.hpp"
#include "app/exercise_scene_check.hpp"
#include "app/exercise_session.hpp"
#include "base/file_io.hpp"
#include "base/paths.hpp"

using namespace fx;
namespace fs = std::filesystem;

namespace {

struct TempDir {
    fs::path path =
        fs::temp_directory_path() /
        ("fx_exercises_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) +
         "_" + std::to_string(::getpid()));
    TempDir() {
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TempDir() { fs::remove_all(path); }
};

void writeText(const fs::path& file, const std::string& text) {
    fs::create_directories(file.parent_path());
    std::ofstream(file) << text;
}

std::string readText(const fs::path& file) {
    auto text = readTextFile(file);
    return text ? *text : "";
}

}  // namespace

TEST(Exercises, EveryShippedExerciseLoadsWithItsFilesAndHints) {
    auto all = loadExercises(exerciseRoot());
    ASSERT_TRUE(all.ok()) << all.error();
    ASSERT_GE(all->size(), 4u);
    for (const Exercise& e : *all) {
        SCOPED_TRACE(e.id());
        EXPECT_TRUE(fs::is_regular_file(e.folder / e.file));
        EXPECT_TRUE(fs::is_regular_file(exerciseRoot() / "solutions" / e.id() / e.file)) << "no solution";
        int wrongAnswers = 0;
        for (const ExerciseHint& hint : e.hints) wrongAnswers += hint.file.empty() ? 0 : 1;
        EXPECT_GE(wrongAnswers, 1) << "every exercise has a typical wrong answer with its hint";
        if (e.kind == "scene") {
            EXPECT_GT(e.budget, 0);
            continue;  // simulated, not rendered: no sizes
        }
        EXPECT_NE(e.reference, e.folder / e.file) << "the starter cannot be the reference";
        bool oddSize = false;
        for (const ExerciseCase& c : e.cases)
            oddSize = oddSize || c.size.width % 2 == 1 || c.size.height % 2 == 1;
        EXPECT_TRUE(oddSize) << "every exercise is checked at an odd size too";
    }
}

TEST(Exercises, ABadExerciseNamesTheFileTheFieldAndTheReason) {
    TempDir dir;
    const fs::path folder = dir.path / "04-7";
    writeText(folder / "a.glsl", "float f() { return 0.0; }\n");
    writeText(folder / "probe.frag", "#version 450 core\n");
    const std::string good = R"({"lesson": 4, "number": 7, "title": "t", "file": "a.glsl",
        "replaces": "shaders/effects/dof/coc.glsl", "probe": "probe.frag", "measures": "m",
        "tolerance": 0.001, "display": {"scale": 0.25, "offset": 0.5}, "cases": [{"size": [3, 3]}]})";
    writeText(folder / "exercise.json", good);
    auto loaded = loadExercise(folder);
    ASSERT_TRUE(loaded.ok()) << loaded.error();
    EXPECT_EQ(loaded->id(), "04-7");
    EXPECT_EQ(loaded->display.scale, 0.25f);
    EXPECT_EQ(loaded->display.offset, 0.5f);

    auto fails = [&](const std::string& from, const std::string& to, const std::string& field) {
        std::string text = good;
        text.replace(text.find(from), from.size(), to);
        writeText(folder / "exercise.json", text);
        auto bad = loadExercise(folder);
        ASSERT_FALSE(bad.ok()) << text;
        EXPECT_NE(bad.error().find("04-7/exercise.json"), std::string::npos) << bad.error();
        EXPECT_NE(bad.error().find(field), std::string::npos) << bad.error();
    };
    fails("\"tolerance\": 0.001", "\"tolerance\": -1", "tolerance");
    fails("[3, 3]", "[0, 3]", "cases[0].size[0]");
    fails("\"a.glsl\"", "\"../a.glsl\"", "file");
    fails("\"probe.frag\"", "\"nowhere.frag\"", "probe");
    fails("\"number\": 7", "\"number\": 8", "folder must be named 04-8");
    fails("\"cases\": [{\"size\": [3, 3]}]", "\"cases\": []", "cases");
    fails("\"title\": \"t\"", "\"title\": \"t\", \"toleranse\": 1", "toleranse");
    // The exercise views' colours: a scale above zero, an offset within [-1, 1], nothing else.
    fails("\"display\": {\"scale\": 0.25, \"offset\": 0.5}, ", "", "display: missing required field");
    fails("\"scale\": 0.25", "\"scale\": 0", "display.scale");
    fails("\"scale\": 0.25", "\"scale\": \"big\"", "display.scale");
    fails("\"scale\": 0.25, ", "", "display.scale");
    fails("\"offset\": 0.5", "\"offset\": 2", "display.offset");
    fails("\"offset\": 0.5", "\"offset\": 0.5, \"gain\": 8", "display.gain");
}

TEST(Exercises, StartCopiesTheStarterAndNeverOverwritesWork) {
    TempDir dir;
    auto all = loadExercises(exerciseRoot());
    ASSERT_TRUE(all.ok() && !all->empty());
    const Exercise& e = all->front();
    auto file = startExercise(e, dir.path);
    ASSERT_TRUE(file.ok()) << file.error();
    EXPECT_EQ(*file, dir.path / e.id() / e.file);
    EXPECT_EQ(readText(*file), readText(e.folder / e.file));
    writeText(*file, "my work\n");
    ASSERT_TRUE(startExercise(e, dir.path).ok());
    EXPECT_EQ(readText(*file), "my work\n");
    // Something that is not a regular file is not replaced.
    fs::remove(*file);
    fs::create_directories(*file);
    auto refused = startExercise(e, dir.path);
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().find("not a regular file"), std::string::npos) << refused.error();
}

TEST(Exercises, ProgressIsKeptPerExerciseBesideTheWork) {
    TempDir dir;
    auto empty = readProgress(dir.path);
    ASSERT_TRUE(empty.ok());
    EXPECT_TRUE(empty->empty());
    ASSERT_TRUE(recordProgress(dir.path, "05-1", {false, "NaN"}).ok());
    ASSERT_TRUE(recordProgress(dir.path, "04-1", {true, "ok"}).ok());
    ASSERT_TRUE(recordProgress(dir.path, "05-1", {true, "fixed"}).ok());
    auto book = readProgress(dir.path);
    ASSERT_TRUE(book.ok()) << book.error();
    ASSERT_EQ(book->size(), 2u);
    EXPECT_TRUE(book->at("05-1").passed);
    EXPECT_EQ(book->at("05-1").message, "fixed");
    writeText(dir.path / "progress.json", "{\"05-1\": {\"passed\": 3}}");
    auto bad = readProgress(dir.path);
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error().find("05-1.passed"), std::string::npos) << bad.error();
    EXPECT_FALSE(recordProgress(dir.path, "04-1", {true, ""}).ok()) << "a bad file is not written over";
}

TEST(Exercises, TheWatchdogEndsAChildThatDoesNotFinish) {
#ifdef _WIN32
    GTEST_SKIP() << "Windows starts the child as this program again, which gtest_main cannot serve: "
                    "tests/windows/watchdog_check.cpp is this test there";
#endif
    registerChildWork("test-hang", [](const std::vector<std::string>&) {
        // Far longer than the watchdog's half second, but finite: with the watchdog broken the
        // test fails in 20 s (finished, too late) instead of hanging until CTest's timeout.
        for (int second = 0; second < 20; ++second) std::this_thread::sleep_for(std::chrono::seconds(1));
        return std::string("finished too late");
    });
    registerChildWork("test-answer", [](const std::vector<std::string>& arguments) {
        return "verdict for " + arguments.at(0);
    });
    registerChildWork("test-abort", [](const std::vector<std::string>&) {
        // SIGABRT, an assert's crash: AddressSanitizer catches SIGSEGV itself and exits
        // instead, so under the sanitizer build the child would not die by a signal.
        std::raise(SIGABRT);
        return std::string();
    });
    const auto start = std::chrono::steady_clock::now();
    ChildOutcome hung = runInChildWithin("test-hang", {}, 0.5);
    EXPECT_EQ(hung.kind, ChildOutcome::Kind::timedOut);
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(10));

    ChildOutcome done = runInChildWithin("test-answer", {"04-2"}, 10.0);
    EXPECT_EQ(done.kind, ChildOutcome::Kind::finished);
    EXPECT_EQ(done.answer, "verdict for 04-2");

    ChildOutcome crashed = runInChildWithin("test-abort", {}, 10.0);
    EXPECT_EQ(crashed.kind, ChildOutcome::Kind::crashed);
    EXPECT_NE(crashed.reason.find("signal"), std::string::npos);

    ChildOutcome unknown = runInChildWithin("no-such-work", {}, 10.0);
    EXPECT_EQ(unknown.kind, ChildOutcome::Kind::notStarted);
    EXPECT_NE(unknown.reason.find("no-such-work"), std::string::npos) << unknown.reason;
}

// The overlay shows an exercise's text from its lesson's lesson.md and lesson.ja.md, like a step's.
TEST(Exercises, EveryExerciseHasItsTextInBothLanguages) {
    auto all = loadExercises(exerciseRoot());
    ASSERT_TRUE(all.ok()) << all.error();
    for (const Exercise& e : *all) {
        SCOPED_TRACE(e.id());
        fs::path folder;
        for (const auto& entry : fs::directory_iterator(projectRoot() / "lessons"))
            if (entry.path().filename().string().starts_with(e.id().substr(0, 2) + "_"))
                folder = entry.path();
        ASSERT_FALSE(folder.empty());
        for (const char* name : {"lesson.md", "lesson.ja.md"}) {
            auto text = exerciseSectionText(readText(folder / name), name, e.number);
            ASSERT_TRUE(text.ok()) << text.error();
            EXPECT_NE(text->find("### Checked exercise"), std::string::npos);
            EXPECT_GT(text->size(), 200u) << *text;
        }
    }
    auto missing = exerciseSectionText("## Step 1: a\n\ntext\n", "lesson.md", 1);
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().find("lesson.md: no section \"## Checked exercise 1"), std::string::npos)
        << missing.error();
}

// Exercise 07-2 is a scene: a rate past the scene format's limits fails with the loader's message (the
// student's file, the field, the limit) and the hint for it; one within the limits but over the
// exercise's budget says how many particles were alive against the budget; no emitter is named.
TEST(Exercises, ASceneExerciseFailsPastTheLimitsOverTheBudgetAndWithoutAnEmitter) {
    auto all = loadExercises(exerciseRoot());
    ASSERT_TRUE(all.ok()) << all.error();
    auto e = findExercise(*all, 7, 2);
    ASSERT_TRUE(e.ok()) << e.error();
    ASSERT_EQ(e->kind, "scene");
    const fs::path wrong = exerciseRoot() / "solutions" / "07-2";

    const ExerciseVerdict limits = checkSceneExercise(*e, wrong / "wrong-past-limits.json");
    EXPECT_FALSE(limits.passed);
    EXPECT_NE(limits.message.find("wrong-past-limits.json"), std::string::npos) << limits.message;
    EXPECT_NE(limits.message.find("emitters[0].rate"), std::string::npos) << limits.message;
    EXPECT_NE(limits.hint.find("did not load"), std::string::npos) << limits.hint;

    const ExerciseVerdict over = checkSceneExercise(*e, wrong / "wrong-over-budget.json");
    EXPECT_FALSE(over.passed);
    EXPECT_GT(over.measured, 2000.0);
    EXPECT_NE(over.message.find("needs <= 2000"), std::string::npos) << over.message;
    EXPECT_NE(over.hint.find("Too many particles"), std::string::npos) << over.hint;

    const ExerciseVerdict starter = checkSceneExercise(*e, e->folder / e->file);
    EXPECT_FALSE(starter.passed);
    EXPECT_NE(starter.message.find("no particle emitter"), std::string::npos) << starter.message;

    const ExerciseVerdict solution = checkSceneExercise(*e, wrong / e->file);
    EXPECT_TRUE(solution.passed) << solution.message;
    EXPECT_GT(solution.measured, 0.0);
    EXPECT_LE(solution.measured, 2000.0);
    EXPECT_EQ(solution.nonFiniteTexels, 0);
}

// Issue 40, defect 7: a scene at the format's limits (256 emitters at rate 10000 x lifetime 10, within
// every scene limit) took the check 157 s and 1.6 GB to fail, and timed out under the watchdog saying
// "does a loop in your shader never end?". Now it is judged from the scene, before any simulation.
TEST(Exercises, ASceneAtTheFormatsLimitsIsJudgedFromTheSceneWithoutSimulating) {
    auto all = loadExercises(exerciseRoot());
    ASSERT_TRUE(all.ok()) << all.error();
    auto e = findExercise(*all, 7, 2);
    ASSERT_TRUE(e.ok()) << e.error();
    auto text = readTextFile(exerciseRoot() / "solutions" / "07-2" / "wrong-over-budget.json");
    ASSERT_TRUE(text.ok());
    nlohmann::json scene = nlohmann::json::parse(*text);
    nlohmann::json emitter = scene["emitters"][0];
    emitter["rate"] = 10000;
    emitter["lifetime"] = 10;
    scene["emitters"] = nlohmann::json::array();
    for (int i = 0; i < 256; ++i) {
        emitter["name"] = "torch" + std::to_string(i);
        scene["emitters"].push_back(emitter);
    }
    const fs::path file =
        fs::temp_directory_path() / ("fx_07-2_limits_" + std::to_string(::getpid()) + ".json");
    ASSERT_TRUE(writeFileAtomically(file, scene.dump()));
    const ExerciseVerdict verdict = checkSceneExercise(*e, file);
    fs::remove(file);
    EXPECT_FALSE(verdict.passed);
    EXPECT_EQ(verdict.measured, 256.0 * 10000 * 10);
    EXPECT_NE(verdict.message.find("256 emitters"), std::string::npos) << verdict.message;
    EXPECT_NE(verdict.message.find("needs <= 2000; judged from your scene without simulating it"),
              std::string::npos)
        << verdict.message;
    EXPECT_NE(verdict.hint.find("Too many particles"), std::string::npos) << verdict.hint;
}
