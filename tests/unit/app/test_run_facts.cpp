// A run keeps the times of its last frames only: a window left open through a lesson does not grow by
// a number a frame (found by the soak, docs/reliability.md).
#include <gtest/gtest.h>

#include "app/run_report.hpp"

TEST(RunFacts, FrameTimesKeepTheLastFramesOnly) {
    fx::RunFacts facts;
    const std::size_t frames = fx::RunFacts::kKeptFrames + 500;
    for (std::size_t i = 0; i < frames; ++i) facts.addFrame(double(i), 2.0 * double(i));
    EXPECT_EQ(facts.framesRun, frames);
    ASSERT_EQ(facts.frameCpuMs.size(), fx::RunFacts::kKeptFrames);
    EXPECT_EQ(facts.frameCpuMs.front(), 500.0);
    EXPECT_EQ(facts.frameGpuMs.back(), 2.0 * double(frames - 1));
    auto report = fx::buildRunReport(facts, {}, {}, {});
    ASSERT_EQ(report["frames"].size(), fx::RunFacts::kKeptFrames);
    EXPECT_EQ(report["frames"][0]["index"], 500u);
    EXPECT_EQ(report["frames"][0]["cpuMs"], 500.0);
}
