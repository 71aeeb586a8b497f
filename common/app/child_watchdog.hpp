#pragma once
// Runs a piece of work in a child process that gets a fixed time: the grader of an exercise survives a
// student's shader that never finishes (a GPU would hang in the draw; Mesa's llvmpipe cuts every
// loop at 65535 iterations, so there it only takes long). The work's answer comes back as text
// through a pipe. Call it before this process has a GL context or threads of its own: a fork copies
// only the calling thread.
#include <functional>
#include <string>

namespace fx {

struct ChildOutcome {
    enum class Kind { finished, timedOut, crashed, notStarted } kind = Kind::notStarted;
    std::string answer;  // what the work returned (finished)
    std::string reason;  // the signal or the error (crashed, notStarted)
};

ChildOutcome runInChildWithin(const std::function<std::string()>& work, double seconds);

}  // namespace fx
