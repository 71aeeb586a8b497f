// The lesson clock: one fixed step a frame whatever the frame took; pause, single step and the compare
// view's hold stop it.
#include <gtest/gtest.h>

#include "app/lesson_clock.hpp"

TEST(LessonClock, EveryFrameIsOneFixedStep) {
    fx::LessonClock clock(0.25);
    EXPECT_DOUBLE_EQ(clock.advance(), 0.25);
    EXPECT_DOUBLE_EQ(clock.advance(), 0.25);
    EXPECT_DOUBLE_EQ(clock.seconds(), 0.5);
    EXPECT_EQ(clock.steps(), 2u);
}

TEST(LessonClock, PauseHoldsTheTimeAndAStepAddsOneFixedStep) {
    fx::LessonClock clock(0.02);
    EXPECT_DOUBLE_EQ(clock.advance(), 0.02);
    clock.togglePause();
    EXPECT_TRUE(clock.paused());
    EXPECT_EQ(clock.advance(), 0.0);
    EXPECT_EQ(clock.advance(), 0.0);
    EXPECT_DOUBLE_EQ(clock.seconds(), 0.02);
    EXPECT_EQ(clock.steps(), 1u) << "a frame that does not move the clock is no step of it";
    clock.stepOnce();
    EXPECT_DOUBLE_EQ(clock.advance(), 0.02);
    EXPECT_EQ(clock.advance(), 0.0);  // one step, then still again
    EXPECT_DOUBLE_EQ(clock.seconds(), 0.04);
    EXPECT_EQ(clock.steps(), 2u);
    clock.togglePause();
    EXPECT_DOUBLE_EQ(clock.advance(), 0.02);
}

TEST(LessonClock, AStepWhileRunningPauses) {
    fx::LessonClock clock(1.0 / 60.0);
    clock.stepOnce();
    EXPECT_TRUE(clock.paused());
    EXPECT_DOUBLE_EQ(clock.advance(), 1.0 / 60.0);
}

TEST(LessonClock, TheCompareViewHoldsItEvenAgainstASingleStep) {
    fx::LessonClock clock(0.5);
    clock.advance();
    clock.hold(true);
    clock.stepOnce();
    EXPECT_EQ(clock.advance(), 0.0);
    EXPECT_DOUBLE_EQ(clock.seconds(), 0.5);
    clock.hold(false);
    EXPECT_TRUE(clock.paused()) << "the \".\" pressed while held paused the clock as it always does";
    EXPECT_DOUBLE_EQ(clock.advance(), 0.5) << "and its step comes once the hold ends";
    EXPECT_EQ(clock.advance(), 0.0);
}
