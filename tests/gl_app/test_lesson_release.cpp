// The runner owns a lesson's GL lifetime: whichever way a run ends (frames done, init failing, a
// program that does not build, a refused --knob), the lesson is destroyed while its GL context is
// still current, so members release their GL objects by destructors alone. Programs the lesson
// builds reach the runner without a list.
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <unistd.h>

#include "app/runner.hpp"
#include "gl/context_guard.hpp"
#include "gl/program.hpp"

namespace fx {
namespace {

namespace fs = std::filesystem;

// What the last probe lesson saw.
struct Seen {
    bool destroyed = false;
    bool contextAliveAtDestruction = false;
    std::size_t programsInRegistry = 0;
};
Seen seen;

enum class Failure { none, init, program };

template <Failure failure>
class ProbeLesson final : public Lesson {
public:
    ~ProbeLesson() override {
        seen.destroyed = true;
        seen.contextAliveAtDestruction = gl::contextAlive();
    }
    std::vector<std::string> steps() const override { return {"one"}; }
    void declareParams(ParamSet& params) override {
        params.addInt("samples", &samples_, 1, 8, "a knob, so that --bench has something").knob =
            Knob{{1, 2}, 2, "samples"};
    }
    Status init(const Scene&) override {
        if (failure == Failure::init) return Error{"probe: init refuses"};
        copy_ = gl::ReloadableProgram({"common/fullscreen.vert",
                                       failure == Failure::program ? "no/such/file.frag" : "common/copy.frag",
                                       {},
                                       {},
                                       "probe copy"});
        seen.programsInRegistry = gl::ProgramRegistry::open() ? gl::ProgramRegistry::open()->size() : 0;
        return Status::success();
    }
    void buildFrame(FrameGraph& graph, const FrameInfo&) override {
        graph.addPass("clear", {})
            .writeColor(graph.output())
            .setState({.clearColor = ClearColor{0, 0, 0, 1}});
    }

private:
    int samples_ = 2;
    gl::ReloadableProgram copy_;
};

class LessonRelease : public ::testing::Test {
protected:
    fs::path dir;
    void SetUp() override {
        seen = {};
        dir = fs::temp_directory_path() / ("fx_release_" + std::to_string(::getpid()));
        fs::create_directories(dir);
    }
    void TearDown() override { fs::remove_all(dir); }

    template <class L>
    int run(std::vector<std::string> args) {
        args.insert(args.begin(), "probe");
        std::vector<char*> argv;
        for (auto& a : args) argv.push_back(a.data());
        return runLesson<L>({0, "probe", "Probe", ""}, int(argv.size()), argv.data());
    }
};

TEST_F(LessonRelease, AfterTheFramesWithTheContextCurrent) {
    int code = run<ProbeLesson<Failure::none>>(
        {"--headless", "--frames", "2", "--size", "32x32", "--report", (dir / "report.json").string()});
    EXPECT_EQ(code, 0);
    EXPECT_TRUE(seen.destroyed);
    EXPECT_TRUE(seen.contextAliveAtDestruction);
    EXPECT_EQ(seen.programsInRegistry, 1u) << "the program joined the runner's registry where it was built";
}

TEST_F(LessonRelease, WhenInitFails) {
    EXPECT_EQ(run<ProbeLesson<Failure::init>>({"--headless", "--frames", "1", "--size", "32x32"}), 1);
    EXPECT_TRUE(seen.destroyed);
    EXPECT_TRUE(seen.contextAliveAtDestruction);
}

TEST_F(LessonRelease, WhenAProgramDoesNotBuild) {
    // init itself succeeds; the runner's check of the registry fails the run.
    EXPECT_EQ(run<ProbeLesson<Failure::program>>({"--headless", "--frames", "1", "--size", "32x32"}), 1);
    EXPECT_TRUE(seen.destroyed);
    EXPECT_TRUE(seen.contextAliveAtDestruction);
}

TEST_F(LessonRelease, WhenTheBenchRefusesItsKnob) {
    EXPECT_EQ(run<ProbeLesson<Failure::none>>({"--bench", "--knob", "nope", "--size", "32x32"}), 2);
    EXPECT_TRUE(seen.destroyed);
    EXPECT_TRUE(seen.contextAliveAtDestruction);
}

}  // namespace
}  // namespace fx
