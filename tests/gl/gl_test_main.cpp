// One headless context for the whole GL test binary; each test fails if the debug callback saw a
// GL error while it ran (GlTest::TearDown).
#include <gtest/gtest.h>

#include "gl_test.hpp"

namespace {
std::unique_ptr<fx::Context> sharedContext;
}

fx::Context& GlTest::context() {
    return *sharedContext;
}

void GlTest::SetUp() {
    ASSERT_TRUE(sharedContext) << "no headless GL context";
    errorsBefore_ = fx::gl::debugCounters().errors;
}

::testing::AssertionResult GlTest::programsBuilt() const {
    if (auto error = programs_.firstUnusable()) return ::testing::AssertionFailure() << *error;
    return ::testing::AssertionSuccess();
}

void GlTest::TearDown() {
    if (!brokenProgramsExpected_) {
        EXPECT_TRUE(programsBuilt());
    }
    fx::gl::drainErrorFlags();
    EXPECT_EQ(fx::gl::debugCounters().errors, errorsBefore_)
        << "GL error during the test: " << fx::gl::debugCounters().lastError;
}

int main(int argc, char** argv) {
    ::testing::InitGoogleTest(&argc, argv);
    // gtest_discover_tests lists the tests without running them: no context is needed for that.
    bool listing = ::testing::GTEST_FLAG(list_tests);
    if (!listing) {
        fx::ContextOptions options;
        options.size = {64, 64};
        auto context = fx::createHeadlessContext(options);
        if (!context) {
            std::fprintf(stderr, "%s\n", context.error().c_str());
            return 1;
        }
        sharedContext = std::move(*context);
    }
    int result = RUN_ALL_TESTS();
    sharedContext.reset();
    return result;
}
