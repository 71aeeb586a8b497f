#pragma once
// Runs a piece of work in a child process that gets a fixed time: the grader of an exercise survives a
// student's shader that never finishes (a GPU would hang in the draw; Mesa's llvmpipe cuts every
// loop at 65535 iterations, so there it only takes long). The work's answer comes back as text
// through a pipe.
//
// The work is found by name, so that a child can run it on either system: on POSIX the child is a
// fork that calls it at once (call it before this process has a GL context or threads of its own: a
// fork copies only the calling thread); Windows has no fork, so this program is started again as
// `PROGRAM --fx-child NAME ARG...`, and its main() hands that to runChildWorkIfAsked before anything
// else (child_watchdog_posix.cpp, child_watchdog_win.cpp).
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace fx {

struct ChildOutcome {
    enum class Kind { finished, timedOut, crashed, notStarted } kind = Kind::notStarted;
    std::string answer;  // what the work returned (finished)
    std::string reason;  // the signal, the exit code or the error (crashed, notStarted)
};

using ChildWork = std::function<std::string(const std::vector<std::string>& arguments)>;

// Makes `work` known as `name` (again: the same name replaces it).
void registerChildWork(const std::string& name, ChildWork work);

// Runs the work registered as `name` with `arguments` in a child, which gets `seconds`.
ChildOutcome runInChildWithin(const std::string& name, const std::vector<std::string>& arguments,
                              double seconds);

// When this process was started as a child (its arguments `--fx-child NAME ARG...`, from
// programArguments): runs the work, writes its answer to standard output and returns the exit code
// main() returns. Otherwise nothing.
std::optional<int> runChildWorkIfAsked(const std::vector<std::string>& arguments);

namespace detail {
// The work registered as `name`, or nothing.
const ChildWork* findChildWork(const std::string& name);
inline constexpr const char* kChildFlag = "--fx-child";
}  // namespace detail

}  // namespace fx
