// fxlab-exercise: the exercises (課題) from the command line. The fxlab script calls it:
//   ./fxlab exercise list            every exercise, and whether this student's last check passed
//   ./fxlab exercise start LL N      copies the starter (then the script opens the lesson at it)
//   ./fxlab check LL N [--json]      grades one; exit 0 passed, 1 failed, 2 a bad command line
//   ./fxlab check --all [--json] [--class DIR]   every exercise; with --class, for each student folder
//   --lang en|ja                     the titles, hints and verdicts in that language (default: the
//                                    locale's, LANG=ja_JP.UTF-8 is Japanese; app/exercise_words.hpp)
// Each check runs in a child process with a watchdog (app/exercise_check.hpp).
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/child_watchdog.hpp"
#include "app/exercise_catalog.hpp"
#include "app/exercise_check.hpp"
#include "app/exercise_words.hpp"
#include "app/process_start.hpp"
#include "base/fatal_error.hpp"
#include "base/json_text.hpp"
#include "base/log.hpp"
#include "base/utf8_path.hpp"
#include "base/words.hpp"

namespace {

namespace fs = std::filesystem;
using namespace fx;

constexpr double kDefaultWatchdogS = 60.0;

int usage() {
    std::cerr
        << "usage: fxlab-exercise list [--json] [--lang en|ja]\n"
           "       fxlab-exercise start LL N\n"
           "       fxlab-exercise check LL N [--json] [--timeout S] [--lang en|ja]\n"
           "       fxlab-exercise check --all [--json] [--timeout S] [--class DIR] [--lang en|ja]\n"
           "--lang: the language of titles, hints and verdicts (default: the locale's, e.g. LANG=ja_JP.UTF-8).\n"
           "The student's work is in $FXLAB_EXERCISES (default ~/fxlab-exercises), one folder per\n"
           "exercise (04-1/); --class DIR grades every student folder in DIR instead.\n";
    return 2;
}

std::optional<int> parseNumber(const std::string& text, int high) {
    if (text.empty() || text.size() > 2 || text.find_first_not_of("0123456789") != std::string::npos)
        return std::nullopt;
    const int value = std::stoi(text);
    return value >= 1 && value <= high ? std::optional<int>(value) : std::nullopt;
}

nlohmann::json verdictObject(const Exercise& e, const fs::path& file, const ExerciseVerdict& v) {
    nlohmann::json json = nlohmann::json::parse(verdictJson(v));
    json["id"] = e.id();
    json["lesson"] = e.lesson;
    json["number"] = e.number;
    json["title"] = e.title;
    json["file"] = file.string();
    return json;
}

void printVerdict(const Exercise& e, const fs::path& file, const ExerciseVerdict& v) {
    const std::string verdict = say(v.passed ? "check.pass" : "check.fail");
    std::cout << say("check.titleLine", {{"id", e.id()}, {"title", e.title}, {"verdict", verdict}}) << "\n"
              << "  " << v.message << "\n";
    if (!v.error.empty() && v.error != v.message)
        std::cout << "  " << v.error << (v.error.ends_with('\n') ? "" : "\n");
    if (!v.hint.empty()) std::cout << "  " << say("check.hintLine", {{"hint", v.hint}}) << "\n";
    std::cout << "  " << say("check.fileLine", {{"file", file.string()}}) << "\n";
}

// Checks `exercises` for the student whose work is in `root`; returns the JSON of the results.
nlohmann::json checkStudent(const std::vector<Exercise>& exercises, const fs::path& root, bool json,
                            bool record, double timeout, int& failures) {
    nlohmann::json results = nlohmann::json::array();
    for (const Exercise& e : exercises) {
        const fs::path file = studentFile(e, root);
        const ExerciseVerdict v = checkExerciseGuarded(e, file, timeout);
        if (!v.passed) ++failures;
        if (record) {
            if (Status saved = recordProgress(root, e.id(), {v.passed, v.message}); !saved)
                std::cerr << "fxlab-exercise: progress not saved: " << saved.error() << "\n";
        }
        if (json)
            results.push_back(verdictObject(e, file, v));
        else
            printVerdict(e, file, v);
    }
    return results;
}

int list(const std::vector<Exercise>& exercises, bool json) {
    const fs::path root = studentRoot();
    auto book = readProgress(root);
    if (!book) {
        std::cerr << "fxlab-exercise: " << book.error() << "\n";
        book = ProgressBook{};
    }
    nlohmann::json out = nlohmann::json::array();
    for (const Exercise& e : exercises) {
        std::error_code ec;
        const bool started = fs::exists(studentFile(e, root), ec);
        auto it = book->find(e.id());
        const std::string state = it != book->end() ? (it->second.passed ? "done" : "failed")
                                  : started         ? "started"
                                                    : "-";
        if (json) {
            out.push_back({{"id", e.id()},
                           {"lesson", e.lesson},
                           {"number", e.number},
                           {"title", e.title},
                           {"state", state}});
            continue;
        }
        std::printf("  %s  %-62s %-8s ./fxlab check %02d %d\n", e.id().c_str(), e.title.c_str(),
                    state.c_str(), e.lesson, e.number);
    }
    if (json)
        std::cout << fx::dumpJson(out, 2) << "\n";
    else
        std::cout << say("check.listFooter", {{"count", cat(exercises.size())}, {"root", root.string()}})
                  << "\n";
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    fx::installFatalErrorHandler("fxlab-exercise");
    // Windows grades in a child that is this program started again (app/child_watchdog.hpp).
    std::vector<std::string> args = fx::programArguments(argc, argv);
    fx::registerExerciseCheckWork();
    if (auto code = fx::runChildWorkIfAsked(args)) return *code;
    if (args.empty()) return usage();
    const std::string command = args.front();
    args.erase(args.begin());
    bool json = false, all = false;
    double timeout = kDefaultWatchdogS;
    fs::path classDir;
    std::string language = languageFromLocale();
    std::vector<std::string> positional;
    for (std::size_t i = 0; i < args.size(); ++i) {
        if (args[i] == "--json")
            json = true;
        else if (args[i] == "--all")
            all = true;
        else if (args[i] == "--timeout" && i + 1 < args.size()) {
            char* end = nullptr;
            timeout = std::strtod(args[++i].c_str(), &end);
            if (*end != '\0' || !(timeout > 0.0 && timeout <= 3600.0)) {
                std::cerr << "fxlab-exercise: --timeout: expected seconds in (0, 3600], got " << args[i]
                          << "\n";
                return 2;
            }
        } else if (args[i] == "--class" && i + 1 < args.size())
            classDir = fx::pathFromUtf8(args[++i]);
        else if (args[i] == "--lang" && i + 1 < args.size()) {
            language = args[++i];
            if (language != "en" && language != "ja") {
                std::cerr << "fxlab-exercise: --lang: expected en or ja, got " << language << "\n";
                return 2;
            }
        } else if (args[i].starts_with("--")) {
            std::cerr << "fxlab-exercise: unknown option " << args[i] << "\n";
            return usage();
        } else
            positional.push_back(args[i]);
    }
    auto exercises = loadExercises(exerciseRoot());
    if (!exercises) {
        std::cerr << "fxlab-exercise: " << exercises.error() << "\n";
        return 1;
    }
    // The student's words: the app's (verdicts) and each exercise's own (title, hints).
    auto words = Words::loadApp(language);
    Status localised = words ? localiseExercises(*exercises, language) : Status(Error{words.error()});
    if (!localised) {
        std::cerr << "fxlab-exercise: " << localised.error() << "\n";
        return 1;
    }
    useWords(std::move(*words));
    if (command == "list") return positional.empty() ? list(*exercises, json) : usage();

    std::vector<Exercise> chosen;
    if (all && positional.empty() && command == "check") {
        chosen = *exercises;
    } else if (!all && positional.size() == 2) {
        auto lesson = parseNumber(positional[0], 99), number = parseNumber(positional[1], 99);
        if (!lesson || !number) {
            std::cerr << "fxlab-exercise: expected a lesson and an exercise number, e.g. 04 1\n";
            return 2;
        }
        auto found = findExercise(*exercises, *lesson, *number);
        if (!found) {
            std::cerr << "fxlab-exercise: " << found.error() << "\n";
            return 2;
        }
        chosen.push_back(*found);
    } else {
        return usage();
    }

    if (command == "start") {
        auto file = startExercise(chosen.front(), studentRoot());
        if (!file) {
            std::cerr << "fxlab-exercise: " << file.error() << "\n";
            return 1;
        }
        std::cout << file->string() << "\n";
        return 0;
    }
    if (command != "check") return usage();

    int failures = 0;
    if (classDir.empty()) {
        nlohmann::json results = checkStudent(chosen, studentRoot(), json, true, timeout, failures);
        if (json)
            std::cout << fx::dumpJson(nlohmann::json{{"student", studentRoot().string()},
                                                     {"passed", chosen.size() - failures},
                                                     {"total", chosen.size()},
                                                     {"exercises", results}},
                                      2)
                      << "\n";
        return failures == 0 ? 0 : 1;
    }
    // A class: every folder in DIR is one student's $FXLAB_EXERCISES; their progress files are left alone.
    std::vector<fs::path> students;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(classDir, ec))
        if (entry.is_directory()) students.push_back(entry.path());
    if (ec) {
        std::cerr << "fxlab-exercise: --class " << classDir.string() << ": " << ec.message() << "\n";
        return 1;
    }
    std::sort(students.begin(), students.end());
    nlohmann::json out = nlohmann::json::array();
    for (const fs::path& student : students) {
        if (!json) std::cout << "== " << student.filename().string() << "\n";
        int failed = 0;
        fx::Doing doing(fx::cat("checking the exercises of ", student.string()));
        nlohmann::json results = checkStudent(chosen, student, json, false, timeout, failed);
        failures += failed;
        out.push_back({{"student", student.filename().string()},
                       {"passed", chosen.size() - failed},
                       {"total", chosen.size()},
                       {"exercises", results}});
    }
    if (json)
        std::cout << fx::dumpJson(nlohmann::json{{"class", classDir.string()}, {"students", out}}, 2) << "\n";
    return failures == 0 ? 0 : 1;
}
