#pragma once
// The last word of a program that meets an error nothing caught: instead of the C++ runtime's
// "terminate called after throwing an instance of ..." and an abort, one line saying which program,
// what it was doing and the error's own words, and exit code 70 (EX_SOFTWARE):
//   fxlab-01-program-objects: an unexpected error while writing the report out/report.json: ...
// Code marks what it is doing with a Doing for as long as it does it (nested: the innermost is named).
#include <string>

namespace fx {

// Replaces std::terminate's handler; `program` names it in the message.
void installFatalErrorHandler(std::string program);

class Doing {
public:
    explicit Doing(std::string what);  // "writing the report out/report.json"
    ~Doing();
    Doing(const Doing&) = delete;
    Doing& operator=(const Doing&) = delete;
};

// What the innermost Doing of this thread says, or "running" when there is none.
std::string whatIsBeingDone();

// The message the handler prints for the exception in flight (for tests and for catch blocks).
std::string fatalErrorMessage(const std::string& program);

}  // namespace fx
