// The POSIX child of child_watchdog.hpp: a fork that runs the work at once.
#include "app/child_watchdog.hpp"

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>

#include "base/log.hpp"

namespace fx {

ChildOutcome runInChildWithin(const std::string& name, const std::vector<std::string>& arguments,
                              double seconds) {
    ChildOutcome outcome;
    const ChildWork* work = detail::findChildWork(name);
    if (!work) {
        outcome.reason = cat("no work named \"", name, "\"");
        return outcome;
    }
    int fds[2];
    if (pipe(fds) != 0) {
        outcome.reason = cat("no pipe: ", std::strerror(errno));
        return outcome;
    }
    std::fflush(nullptr);  // what is buffered would be written twice
    const pid_t child = fork();
    if (child < 0) {
        outcome.reason = cat("fork failed: ", std::strerror(errno));
        close(fds[0]);
        close(fds[1]);
        return outcome;
    }
    if (child == 0) {
        close(fds[0]);
        const std::string answer = (*work)(arguments);
        std::size_t written = 0;
        while (written < answer.size()) {
            const ssize_t n = write(fds[1], answer.data() + written, answer.size() - written);
            if (n <= 0) break;
            written += std::size_t(n);
        }
        _exit(0);  // no destructors of the parent's objects, no atexit handlers twice
    }
    close(fds[1]);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    bool timedOut = false;
    for (;;) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
            deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) {
            timedOut = true;
            break;
        }
        pollfd fd{fds[0], POLLIN, 0};
        if (poll(&fd, 1, int(left.count())) <= 0) continue;  // the time is up, or a signal came
        char buffer[4096];
        const ssize_t n = read(fds[0], buffer, sizeof buffer);
        if (n <= 0) break;  // the child closed its end: done (or gone)
        outcome.answer.append(buffer, std::size_t(n));
    }
    close(fds[0]);
    if (timedOut) kill(child, SIGKILL);  // our own child, by its id
    int status = 0;
    while (waitpid(child, &status, 0) < 0 && errno == EINTR) {
    }
    if (timedOut) {
        outcome.kind = ChildOutcome::Kind::timedOut;
    } else if (WIFSIGNALED(status)) {
        outcome.kind = ChildOutcome::Kind::crashed;
        outcome.reason = cat("signal ", WTERMSIG(status));
    } else {
        outcome.kind = ChildOutcome::Kind::finished;
    }
    return outcome;
}

}  // namespace fx
