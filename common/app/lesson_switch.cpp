#include "app/lesson_switch.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <set>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include "app/run_options.hpp"
#include "base/log.hpp"

extern char** environ;

namespace fx {

namespace fs = std::filesystem;

namespace {

// Flags whose value names something of one lesson, and flags the neighbour gets anew.
const std::set<std::string> kLessonOwnFlags = {"--step", "--scene", "--param", "--preset", "--inspect",
                                               "--knob", "--press", "--size",  "--resize"};
// args without the flags in `drop` (and their values).
std::vector<std::string> without(const std::vector<std::string>& args, const std::set<std::string>& drop) {
    std::vector<std::string> kept;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const bool takesValue = runFlagTakesValue(args[i]);
        if (drop.contains(args[i])) {
            if (takesValue) ++i;
            continue;
        }
        kept.push_back(args[i]);
        if (takesValue && i + 1 < args.size()) kept.push_back(args[++i]);
    }
    return kept;
}

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

bool isLessonExecutableName(const std::string& name) {
    // fxlab-NN-<slug>
    return name.size() > 9 && name.rfind("fxlab-", 0) == 0 &&
           std::isdigit(static_cast<unsigned char>(name[6])) &&
           std::isdigit(static_cast<unsigned char>(name[7])) && name[8] == '-';
}

std::vector<fs::path> lessonExecutables(const fs::path& folder) {
    std::vector<fs::path> found;
    std::error_code ec;
    for (const fs::directory_entry& e : fs::directory_iterator(folder, ec)) {
        const std::string name = e.path().filename().string();
        if (!isLessonExecutableName(name) || !e.is_regular_file(ec)) continue;
        if ((e.status(ec).permissions() & fs::perms::owner_exec) == fs::perms::none) continue;
        found.push_back(e.path());
    }
    std::sort(found.begin(), found.end(),
              [](const fs::path& a, const fs::path& b) { return a.filename() < b.filename(); });
    return found;
}

std::optional<fs::path> neighbourIn(const std::vector<fs::path>& executables, const std::string& current,
                                    int direction) {
    auto it = std::find_if(executables.begin(), executables.end(),
                           [&](const fs::path& p) { return p.filename() == current; });
    if (it == executables.end()) return std::nullopt;
    const auto index = std::distance(executables.begin(), it) + direction;
    if (index < 0 || index >= std::ssize(executables)) return std::nullopt;
    return executables[std::size_t(index)];
}

std::optional<fs::path> neighbourLesson(const std::string& current, int direction) {
    return neighbourIn(lessonExecutables(runningExecutable().parent_path()), current, direction);
}

std::vector<std::string> neighbourArguments(const std::vector<std::string>& args, Size2D window) {
    std::vector<std::string> next = without(args, kLessonOwnFlags);
    if (!window.empty()) {
        next.push_back("--size");
        next.push_back(toString(window));
    }
    return next;
}

std::vector<std::string> stepCaptureArguments(const std::vector<std::string>& args,
                                              const fs::path& captureDir, int step) {
    std::vector<std::string> one =
        without(args, {"--all-steps", "--capture", "--report", "--step", "--graph"});
    // Headless: a fixed time step, the same pictures every time, and a run that ends by itself (a
    // window without --frames would run until closed).
    if (std::find(one.begin(), one.end(), "--headless") == one.end()) one.insert(one.begin(), "--headless");
    const fs::path folder = captureDir / cat("step-", step);
    for (std::string a : {std::string("--step"), cat(step), std::string("--capture"), folder.string(),
                          std::string("--report"), (folder / "report.json").string(), std::string("--graph"),
                          (folder / "graph.dot").string()})
        one.push_back(std::move(a));
    return one;
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
