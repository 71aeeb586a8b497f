// An error nothing caught ends with a line naming the program and what it was doing (issue 40,
// defect 3), not "terminate called after throwing an instance of ..." and an abort.
#include <gtest/gtest.h>

#include <stdexcept>

#include <nlohmann/json.hpp>

#include "base/fatal_error.hpp"

TEST(FatalError, TheMessageNamesTheProgramWhatItWasDoingAndTheError) {
    fx::Doing outer("running fxlab-01");
    std::string message;
    try {
        fx::Doing inner("writing the report out/r\xff.json");
        throw std::runtime_error("disk on fire");
    } catch (...) {
        message = fx::fatalErrorMessage("fxlab-01");
    }
    // The inner Doing is gone once its scope is left by the exception; the outer one is named.
    EXPECT_EQ(message.rfind("fxlab-01: an unexpected error while running fxlab-01: disk on fire", 0), 0u)
        << message;
    EXPECT_EQ(fx::whatIsBeingDone(), "running fxlab-01");
}

namespace {

// The error leaves this function uncaught (noexcept), as it would leave main.
void writeAReportNamed(const char* scene) noexcept {
    fx::Doing doing(std::string("writing the report out/") + scene);
    nlohmann::json j;
    j["scene"] = scene;
    (void)j.dump();  // type_error.316
}

}  // namespace

TEST(FatalError, AnUncaughtExceptionEndsTheProgramWithTheMessageAndCode70) {
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    EXPECT_EXIT(
        (fx::installFatalErrorHandler("fxlab-test"), writeAReportNamed("sc\xff.json")),
        ::testing::ExitedWithCode(70),
        "fxlab-test: an unexpected error while writing the report out/sc\\\\xff.json: .*type_error.316");
}
