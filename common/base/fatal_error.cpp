#include "base/fatal_error.hpp"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <vector>

#include "base/json_text.hpp"

namespace fx {
namespace {

thread_local std::vector<std::string> doing;
std::string programName = "fxlab";

[[noreturn]] void onTerminate() {
    const std::string message = fatalErrorMessage(programName);
    std::fputs(message.c_str(), stderr);
    std::fputc('\n', stderr);
    std::fflush(stderr);
    std::_Exit(70);
}

}  // namespace

Doing::Doing(std::string what) {
    doing.push_back(std::move(what));
}

Doing::~Doing() {
    doing.pop_back();
}

std::string whatIsBeingDone() {
    return doing.empty() ? std::string("running") : doing.back();
}

std::string fatalErrorMessage(const std::string& program) {
    std::string reason = "no error in flight";
    if (std::exception_ptr error = std::current_exception()) {
        try {
            std::rethrow_exception(error);
        } catch (const std::exception& e) {
            reason = e.what();
        } catch (...) {
            reason = "an error of a kind fxlab does not know";
        }
    }
    return utf8Escaped(program + ": an unexpected error while " + whatIsBeingDone() + ": " + reason +
                       " (this is a fault of fxlab's; please report it with the command that led here)");
}

void installFatalErrorHandler(std::string program) {
    programName = std::move(program);
    std::set_terminate(onTerminate);
}

}  // namespace fx
