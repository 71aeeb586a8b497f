#pragma once
#include <gtest/gtest.h>

#include "gl/debug_output.hpp"
#include "gl/program.hpp"
#include "platform/context.hpp"

// Base fixture for tests that need GL: the context is shared, GL errors fail the test, and so does a
// program that never built (effects build theirs when they are made, members of the test included).
class GlTest : public ::testing::Test {
protected:
    static fx::Context& context();
    void SetUp() override;
    void TearDown() override;

    // Every program made since the test's fixture was made built; otherwise the first one's error.
    ::testing::AssertionResult programsBuilt() const;
    // The test builds a program that does not build, on purpose.
    void expectBrokenPrograms() { brokenProgramsExpected_ = true; }

private:
    fx::gl::ProgramRegistry programs_;  // a base member: open before the test's own members are made
    std::int64_t errorsBefore_ = 0;
    bool brokenProgramsExpected_ = false;
};
