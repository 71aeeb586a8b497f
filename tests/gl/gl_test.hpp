#pragma once
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "gl/debug_output.hpp"
#include "gl/program.hpp"
#include "image/image.hpp"
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

// No NaN and no infinity in any channel of a read-back image (the hard cases' first check).
inline bool allFinite(const fx::FloatImage& image) {
    return std::all_of(image.texels.begin(), image.texels.end(), [](float v) { return std::isfinite(v); });
}
