// The class controls through the runner (headless: --press drives the same key table a window uses):
// space holds the lesson's clock still while frames go on, "." moves it one fixed step, F3 compares two
// steps at one moment, and with the overlay the picture gets its own place beside the panels.
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <unistd.h>
#include <nlohmann/json.hpp>

#include "app/runner.hpp"
#include "base/file_io.hpp"

namespace fx {
namespace {

namespace fs = std::filesystem;

// The time, clock step, step and size each frame handed the lesson.
std::vector<double> seconds;
std::vector<std::uint64_t> clockSteps;
std::vector<int> stepsBuilt;
std::vector<Size2D> sizes;

class ClockProbe final : public Lesson {
public:
    std::vector<std::string> steps() const override { return {"one", "two"}; }
    Status init(const Scene&) override { return Status::success(); }
    void update(const FrameInfo& frame) override {
        seconds.push_back(frame.seconds);
        clockSteps.push_back(frame.clockSteps);
        stepsBuilt.push_back(frame.step);
        sizes.push_back(frame.size);
    }
    void buildFrame(FrameGraph& graph, const FrameInfo&) override {
        graph.addPass("clear", {})
            .writeColor(graph.output())
            .setState({.clearColor = ClearColor{0.2f, 0.4f, 0.8f, 1}});
    }
};

int run(const std::vector<std::string>& flags) {
    seconds.clear();
    clockSteps.clear();
    stepsBuilt.clear();
    sizes.clear();
    std::vector<std::string> args = {"probe"};
    for (const std::string& f : flags) args.push_back(f);
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    return runLesson<ClockProbe>({0, "clock-probe", "Clock probe", ""}, int(argv.size()), argv.data());
}

TEST(ClassControls, SpaceHoldsTheClockAndAPeriodMovesItOneStep) {
    ASSERT_EQ(run({"--headless", "--size", "32x32", "--frames", "7", "--time-step", "0.5", "--press",
                   "space@2", "--press", "period@4", "--press", "space@6"}),
              0);
    ASSERT_EQ(seconds.size(), 7u);
    // Frames 0 and 1 run; space at frame 2 holds the time of frame 1; "." at 4 adds one step; space at
    // 6 lets it run again.
    EXPECT_EQ(seconds, (std::vector<double>{0.5, 1.0, 1.0, 1.0, 1.5, 1.5, 2.0}));
    // The frame's number on the lesson clock: what a step that acts every Nth frame counts.
    EXPECT_EQ(clockSteps, (std::vector<std::uint64_t>{1, 2, 2, 2, 3, 3, 4}));
}

TEST(ClassControls, TheCompareViewShowsBothStepsAtOneMoment) {
    // Step 2 from frame 2 on; F3 at frame 5 holds the clock and draws step 1 again at that moment
    // before step 2's frame, so the two pictures compared are of the same time.
    ASSERT_EQ(run({"--headless", "--overlay", "--size", "320x180", "--frames", "8", "--time-step", "0.5",
                   "--press", "right@2", "--press", "F3@5"}),
              0);
    EXPECT_EQ(stepsBuilt, (std::vector<int>{0, 0, 1, 1, 1, 0, 1, 1, 1}));
    EXPECT_EQ(seconds, (std::vector<double>{0.5, 1.0, 1.5, 2.0, 2.5, 2.5, 2.5, 2.5, 2.5}));
}

TEST(ClassControls, WithTheOverlayThePictureHasItsOwnPlace) {
    const fs::path dir = fs::temp_directory_path() / ("fx_class_controls_" + std::to_string(::getpid()));
    ASSERT_EQ(run({"--headless", "--overlay", "--size", "1280x720", "--frames", "2", "--capture",
                   dir.string(), "--report", (dir / "report.json").string()}),
              0);
    // The lesson rendered at the picture's size: the window less the panel column, at 16:9.
    ASSERT_FALSE(sizes.empty());
    EXPECT_EQ(sizes.back(), (Size2D{896, 504}));
    auto text = readTextFile(dir / "report.json");
    ASSERT_TRUE(text);
    auto report = nlohmann::json::parse(*text);
    EXPECT_EQ(report["glErrors"], 0);
    EXPECT_EQ(report["layout"]["picture"], (nlohmann::json{384, 108, 896, 504}));
    EXPECT_EQ(report["picture"]["rendered"], (nlohmann::json{896, 504}))
        << "headless: never scaled by itself";
    EXPECT_TRUE(fs::exists(dir / "picture.png"));
    EXPECT_TRUE(fs::exists(dir / "final.png"));
    fs::remove_all(dir);
}

}  // namespace
}  // namespace fx
