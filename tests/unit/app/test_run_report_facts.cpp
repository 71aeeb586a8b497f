// The report's facts (app/run_report.hpp): every fact by name for the scripts, and the facts the
// overlay's panel shows, in its words and order, for the handout.
#include <gtest/gtest.h>

#include "app/lesson_facts.hpp"
#include "app/run_report.hpp"

namespace {

TEST(RunReport, WritesEveryFactByNameAndTheShownOnesAsThePanelWordsThem) {
    fx::RunFacts facts;
    facts.lessonFacts = {{"levels", "6"}, {"expectErrorsInStep", "true"}};
    facts.shownFacts = {{"levels (of 6 asked for)", "6"}};
    const auto report = fx::buildRunReport(facts, fx::FrameReport{}, {}, fx::FloatImage{});
    EXPECT_EQ(report["facts"]["levels"], "6");
    EXPECT_EQ(report["facts"]["expectErrorsInStep"], true);
    ASSERT_EQ(report["shownFacts"].size(), 1u);
    EXPECT_EQ(report["shownFacts"][0]["label"], "levels (of 6 asked for)");
    EXPECT_EQ(report["shownFacts"][0]["value"], "6");
}

TEST(RunReport, APanelShowsAFactUnderItsLabelOrItsName) {
    EXPECT_EQ((fx::Fact{"levels", "6", "levels (of 6 asked for)"}.shownLabel()), "levels (of 6 asked for)");
    EXPECT_EQ((fx::Fact{"levels", "6", ""}.shownLabel()), "levels");
}

}  // namespace
