// The POSIX side of lesson_switch.hpp: exec in place, posix_spawn and wait, /proc/self/exe.
#include "app/lesson_switch.hpp"

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include "base/log.hpp"

extern char** environ;

namespace fx {

namespace fs = std::filesystem;

namespace {

std::vector<char*> argv(const fs::path& executable, const std::vector<std::string>& args,
                        std::string& program) {
    program = executable.string();
    std::vector<char*> v;
    v.push_back(program.data());
    for (const std::string& a : args) v.push_back(const_cast<char*>(a.c_str()));
    v.push_back(nullptr);
    return v;
}

}  // namespace

bool isRunnableFile(const fs::directory_entry& entry) {
    std::error_code ec;
    return entry.is_regular_file(ec) &&
           (entry.status(ec).permissions() & fs::perms::owner_exec) != fs::perms::none;
}

std::string programName(const fs::path& executable) {
    return executable.filename().string();
}

Error execLesson(const fs::path& executable, const std::vector<std::string>& args) {
    std::string program;
    std::vector<char*> v = argv(executable, args, program);
    execv(program.c_str(), v.data());
    return Error{cat("could not start ", program, ": ", std::strerror(errno))};
}

Result<int> runAndWait(const fs::path& executable, const std::vector<std::string>& args,
                       const fs::path& output) {
    std::string program;
    std::vector<char*> v = argv(executable, args, program);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    if (!output.empty()) {
        posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, output.c_str(),
                                         O_WRONLY | O_CREAT | O_TRUNC, 0644);
        posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
    }
    pid_t child = 0;
    int error = posix_spawn(&child, program.c_str(), &actions, nullptr, v.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (error != 0) return Error{cat("could not start ", program, ": ", std::strerror(error))};
    int status = 0;
    while (waitpid(child, &status, 0) < 0) {
        if (errno != EINTR) return Error{cat("waiting for ", program, ": ", std::strerror(errno))};
    }
    if (WIFEXITED(status)) return WEXITSTATUS(status);
    return Error{cat(program, " ended by signal ", WTERMSIG(status))};
}

fs::path runningExecutable() {
    std::error_code ec;
    fs::path self = fs::read_symlink("/proc/self/exe", ec);
    return ec ? fs::path() : self;
}

}  // namespace fx
