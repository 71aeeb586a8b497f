// Pause and single-step: the lesson's time stands still while paused and moves one fixed step per ".".
#include <gtest/gtest.h>

#include "app/lesson_clock.hpp"

TEST(LessonClock, PauseHoldsTheTimeAndAStepAddsOneFixedStep) {
    fx::LessonClock clock(0.02);
    EXPECT_DOUBLE_EQ(clock.advance(0.5), 0.5);
    clock.togglePause();
    EXPECT_TRUE(clock.paused());
    EXPECT_EQ(clock.advance(0.5), 0.0);
    EXPECT_EQ(clock.advance(0.5), 0.0);
    EXPECT_DOUBLE_EQ(clock.seconds(), 0.5);
    clock.stepOnce();
    EXPECT_DOUBLE_EQ(clock.advance(0.5), 0.02);
    EXPECT_EQ(clock.advance(0.5), 0.0);  // one step, then still again
    EXPECT_DOUBLE_EQ(clock.seconds(), 0.52);
    clock.togglePause();
    EXPECT_DOUBLE_EQ(clock.advance(0.1), 0.1);
}

TEST(LessonClock, AStepWhileRunningPauses) {
    fx::LessonClock clock(1.0 / 60.0);
    clock.stepOnce();
    EXPECT_TRUE(clock.paused());
    EXPECT_DOUBLE_EQ(clock.advance(3.0), 1.0 / 60.0);
}
