#pragma once
#include <gtest/gtest.h>

#include "gl/debug_output.hpp"
#include "platform/context.hpp"

// Base fixture for tests that need GL: the context is shared, GL errors fail the test.
class GlTest : public ::testing::Test {
protected:
    static fx::Context& context();
    void SetUp() override;
    void TearDown() override;

private:
    std::int64_t errorsBefore_ = 0;
};
