// An error nothing caught ends with a line naming the program and what it was doing (issue 40,
// defect 3), not "terminate called after throwing an instance of ..." and an abort.
#include <gtest/gtest.h>

#include <stdexcept>
#include <thread>

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

// The error leaves this function uncaught, as it would leave main. It runs on a thread of its own: a
// thread's start has no handler, so the runtime calls std::terminate without unwinding, whatever the
// compiler (an exception leaving a noexcept function is unwound first by clang and not by GCC, and
// the Doing would be gone under clang).
void writeAReportNamed(const char* scene) {
    fx::Doing doing(std::string("writing the report out/") + scene);
    nlohmann::json j;
    j["scene"] = scene;
    (void)j.dump();  // type_error.316
}

}  // namespace

TEST(FatalError, AnUncaughtExceptionEndsTheProgramWithTheMessageAndCode70) {
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    EXPECT_EXIT(
        {
            fx::installFatalErrorHandler("fxlab-test");
            std::thread([] { writeAReportNamed("sc\xff.json"); }).join();
        },
        ::testing::ExitedWithCode(70),
        "fxlab-test: an unexpected error while writing the report out/sc\\\\xff.json: .*type_error.316");
}
