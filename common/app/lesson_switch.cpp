#include "app/lesson_switch.hpp"

#include <algorithm>
#include <set>

#include "app/run_options.hpp"
#include "base/log.hpp"

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
        if (!isLessonExecutableName(name) || !isRunnableFile(e)) continue;
        found.push_back(e.path());
    }
    std::sort(found.begin(), found.end(),
              [](const fs::path& a, const fs::path& b) { return a.filename() < b.filename(); });
    return found;
}

std::optional<fs::path> neighbourIn(const std::vector<fs::path>& executables, const std::string& current,
                                    int direction) {
    auto it = std::find_if(executables.begin(), executables.end(),
                           [&](const fs::path& p) { return programName(p) == current; });
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

}  // namespace fx
