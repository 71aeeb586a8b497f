// Facts and parameters belong to their step, through the runner: a value the teacher changed in one
// step is not the next step's (lesson 01 step 2 opened with step 1's broken_shader=none and showed
// nothing), it comes back with its step, and the count of GL errors a step shows on purpose starts at
// each step (lesson 01 step 3 said "26982", step 1's count).
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <unistd.h>
#include <nlohmann/json.hpp>

#include "app/runner.hpp"
#include "base/file_io.hpp"
#include "gl/debug_output.hpp"

namespace fx {
namespace {

namespace fs = std::filesystem;

std::vector<int> seen;  // the broken value each frame's update saw

class StepProbe final : public Lesson {
public:
    std::vector<std::string> steps() const override { return {"unchecked", "checked", "other"}; }
    void declareParams(ParamSet& params) override {
        params_ = &params;
        params.addChoice("broken", &broken_, {"none", "broken"}, "steps 1 and 2").inSteps({0, 1});
    }
    Status init(const Scene&) override { return Status::success(); }
    void update(const FrameInfo& frame) override {
        seen.push_back(broken_);
        if (frame.step == 0 && broken_ == 1) {
            // Step 1 shows a GL error on purpose while its shader is broken.
            gl::ExpectedErrorScope onPurpose("the probe's step 1");
            glBindTexture(GL_TEXTURE_2D, 987654);  // not a name: GL_INVALID_OPERATION
        }
        // The teacher sets it to none in step 1's second frame, as the overlay's combo does.
        if (frame.index == 1 && frame.step == 0) {
            broken_ = 0;
            params_->markEdited(*params_->find("broken"));
        }
    }
    void buildFrame(FrameGraph& graph, const FrameInfo&) override {
        graph.addPass("clear", {})
            .writeColor(graph.output())
            .setState({.clearColor = ClearColor{0.2f, 0.4f, 0.8f, 1}});
    }

private:
    ParamSet* params_ = nullptr;
    int broken_ = 1;
};

nlohmann::json run(const std::vector<std::string>& flags) {
    seen.clear();
    const fs::path dir = fs::temp_directory_path() / ("fx_step_params_" + std::to_string(::getpid()));
    std::vector<std::string> args = {"probe", "--headless", "--size",
                                     "32x32", "--report",   (dir / "report.json").string()};
    for (const std::string& f : flags) args.push_back(f);
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    const int code = runLesson<StepProbe>({0, "step-probe", "Step probe", ""}, int(argv.size()), argv.data());
    EXPECT_EQ(code, 0);
    auto text = readTextFile(dir / "report.json");
    fs::remove_all(dir);
    return text ? nlohmann::json::parse(*text) : nlohmann::json{};
}

TEST(StepParams, AChangeStaysWithItsStepAndTheNextStepOpensWithItsOwn) {
    // Step 2 at frame 3, back to step 1 at frame 5.
    const nlohmann::json report = run({"--frames", "7", "--press", "right@3", "--press", "left@5"});
    EXPECT_EQ(seen, (std::vector<int>{1, 1, 0, 1, 1, 0, 0}))
        << "step 2 opens with its own broken value; back in step 1, the teacher's none";
    ASSERT_TRUE(report.contains("params"));
    EXPECT_EQ(report["params"][0]["source"], "overlay");
}

TEST(StepParams, TheErrorsAStepShowsOnPurposeAreCountedPerStep) {
    const nlohmann::json first = run({"--frames", "2"});
    EXPECT_GT(first["glExpectedErrors"].get<int>(), 0);
    EXPECT_EQ(first["glExpectedErrorsThisStep"], first["glExpectedErrors"]) << "all of them in step 1";
    EXPECT_EQ(first["glErrors"], 0);
    const nlohmann::json later = run({"--frames", "4", "--press", "right@2", "--press", "right@3"});
    EXPECT_GT(later["glExpectedErrors"].get<int>(), 0) << "step 1 showed its errors";
    EXPECT_EQ(later["glExpectedErrorsThisStep"], 0) << "step 3 shows none: step 1's count is not its own";
}

}  // namespace
}  // namespace fx
