#include "app/exercise_catalog.hpp"
#include "base/json_text.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <regex>

#include <nlohmann/json.hpp>

#include "base/file_io.hpp"
#include "base/paths.hpp"
#include "base/user_folders.hpp"
#include "base/utf8_path.hpp"
#include "scene/json_field_reader.hpp"

namespace fx {
namespace {

namespace fs = std::filesystem;

constexpr std::size_t kMaxCases = 16;
constexpr std::size_t kMaxHints = 16;
constexpr int kMaxCaseSide = 1024;  // a check renders every case several times: keep it small

ExerciseUniform readUniform(const std::string& name, const nlohmann::json& value, const std::string& path) {
    ExerciseUniform uniform{name, {}, {}};
    if (value.is_string()) {
        uniform.special = value.get<std::string>();
        if (uniform.special != "size" && uniform.special != "centre")
            failField(path, cat("unknown value \"", uniform.special,
                                "\" (expected a number, an array of 2 to 4 "
                                "numbers, \"size\" or \"centre\")"));
        return uniform;
    }
    if (value.is_number()) {
        uniform.values.push_back(readNumber(value, path, NumberRange{}));
        return uniform;
    }
    if (!value.is_array() || value.size() < 2 || value.size() > 4)
        failField(path, cat("expected a number, an array of 2 to 4 numbers, \"size\" or \"centre\"; got ",
                            describeJsonType(value)));
    uniform.values.resize(value.size());
    readNumbers(value, path, uniform.values.data(), int(value.size()), NumberRange{});
    return uniform;
}

ExerciseCase readCase(JsonFieldReader& in) {
    ExerciseCase c;
    const nlohmann::json& size = in.required("size");
    int wh[2] = {0, 0};
    if (!size.is_array() || size.size() != 2) in.fail("size", "expected [width, height]");
    for (int i = 0; i < 2; ++i)
        wh[i] = readInteger(size[i], indexPath(in.pathOf("size"), i), NumberRange::closed(1, kMaxCaseSide));
    c.size = {wh[0], wh[1]};
    if (in.has("uniforms")) {
        const nlohmann::json& uniforms = in.required("uniforms");
        if (!uniforms.is_object())
            in.fail("uniforms", cat("expected an object, got ", describeJsonType(uniforms)));
        for (const auto& [name, value] : uniforms.items())
            c.uniforms.push_back(readUniform(name, value, fieldPath(in.pathOf("uniforms"), name)));
    }
    in.reportUnknown();
    return c;
}

// A path in the project ("shaders/effects/dof/coc.glsl"), which must exist as a regular file.
fs::path projectFile(JsonFieldReader& in, std::string_view key, const fs::path& base) {
    fs::path file = (base / in.requiredText(key)).lexically_normal();
    std::error_code ec;
    if (!fs::is_regular_file(file, ec)) in.fail(key, cat("no such file: ", file.string()));
    return file;
}

}  // namespace

std::string Exercise::id() const {
    char text[32];
    std::snprintf(text, sizeof text, "%02d-%d", lesson, number);
    return text;
}

Result<Exercise> loadExercise(const fs::path& folder) {
    const fs::path file = folder / "exercise.json";
    auto text = readFile(file, file_limits::preset);
    if (!text) return Error{text.error()};
    nlohmann::json json;
    try {
        json = nlohmann::json::parse(*text);
    } catch (const nlohmann::json::parse_error& e) {
        return Error{cat(file.string(), ": not JSON: ", e.what())};
    }
    std::vector<std::string> warnings;
    Exercise exercise;
    exercise.folder = folder.lexically_normal();
    try {
        JsonFieldReader in(json, "", warnings);
        exercise.lesson = in.integer("lesson", 0, NumberRange::closed(1, 99));
        exercise.number = in.integer("number", 0, NumberRange::closed(1, 99));
        if (!in.has("lesson") || !in.has("number"))
            in.fail(in.has("lesson") ? "number" : "lesson", "missing");
        if (folder.filename() != exercise.id())
            in.fail("number", cat("the folder must be named ", exercise.id(), " (it is ",
                                  folder.filename().string(), ")"));
        exercise.title = in.requiredText("title");
        exercise.step = in.integer("step", 1, NumberRange::closed(1, 64));
        exercise.file = in.requiredText("file");
        if (exercise.file.find('/') != std::string::npos || exercise.file.starts_with("."))
            in.fail("file", "a file name in the exercise's folder, without a folder");
        const fs::path starter = folder / exercise.file;
        if (std::error_code ec; !fs::is_regular_file(starter, ec))
            in.fail("file", cat("no starter ", starter.string()));
        exercise.kind = in.text("kind", "probe");
        if (exercise.kind == "scene") {
            // The student's scene is checked by simulating it: no probe, no reference, no cases.
            exercise.replaces = exercise.reference = starter.lexically_normal();
            exercise.budget = in.integer("budget", 0, NumberRange::closed(1, 100000));
            if (!in.has("budget")) in.fail("budget", "missing (a scene exercise's most particles alive)");
            exercise.seconds = in.number("seconds", 10.0f, NumberRange::closed(0.1, 60.0));
            exercise.measure = "liveParticles";
            exercise.tolerance = exercise.budget;
            exercise.measures = in.requiredText("measures");
        } else if (exercise.kind == "probe") {
            exercise.replaces = projectFile(in, "replaces", projectRoot());
            exercise.reference =
                in.has("reference") ? projectFile(in, "reference", projectRoot()) : exercise.replaces;
            exercise.probe = projectFile(in, "probe", folder);
            in.forEachObject("cases", kMaxCases,
                             [&](JsonFieldReader& c) { exercise.cases.push_back(readCase(c)); });
            if (exercise.cases.empty()) in.fail("cases", "an exercise needs at least one case");
            exercise.measure = in.text("measure", "maxAbs");
            if (exercise.measure != "maxAbs" && exercise.measure != "rmse")
                in.fail("measure", cat("unknown measure \"", exercise.measure, "\" (maxAbs or rmse)"));
            exercise.tolerance = in.requiredNumber("tolerance", NumberRange::aboveZero(1e6));
            exercise.measures = in.requiredText("measures");
            JsonFieldReader display = in.object("display");
            exercise.display.scale = display.requiredNumber("scale", NumberRange::aboveZero(1e6));
            exercise.display.offset = display.number("offset", 0.0f, NumberRange::closed(-1.0, 1.0));
            display.reportUnknown();
        } else {
            in.fail("kind", cat("unknown value \"", exercise.kind, "\" (probe or scene)"));
        }
        in.forEachObject("hints", kMaxHints, [&](JsonFieldReader& h) {
            ExerciseHint hint;
            hint.when = h.requiredText("when");
            const bool scene = exercise.kind == "scene";
            const bool known =
                hint.when == "nonFinite" || hint.when == "fails" || (!scene && hint.when == "matches") ||
                (scene && (hint.when == "invalid" || hint.when == "noEmitter" || hint.when == "overBudget"));
            if (!known)
                h.fail("when", cat("unknown value \"", hint.when, "\" (",
                                   scene ? "nonFinite, invalid, noEmitter, overBudget or fails"
                                         : "nonFinite, matches or fails",
                                   ")"));
            if (hint.when == "matches" || h.has("file")) hint.file = projectFile(h, "file", exerciseRoot());
            hint.text = h.requiredText("text");
            h.reportUnknown();
            exercise.hints.push_back(std::move(hint));
        });
        in.reportUnknown();
    } catch (const SceneFieldError& e) {
        return Error{cat(file.string(), ": ", e.path, ": ", e.reason)};
    }
    if (!warnings.empty()) return Error{cat(file.string(), ": ", warnings.front())};
    return exercise;
}

fs::path exerciseRoot() {
    return projectRoot() / "exercises";
}

Result<std::vector<Exercise>> loadExercises(const fs::path& root) {
    static const std::regex name(R"(\d\d-\d+)");
    std::vector<Exercise> all;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(root, ec)) {
        if (!entry.is_directory() || !std::regex_match(entry.path().filename().string(), name)) continue;
        auto exercise = loadExercise(entry.path());
        if (!exercise) return Error{exercise.error()};
        all.push_back(std::move(*exercise));
    }
    if (ec) return Error{cat(root.string(), ": ", ec.message())};
    std::sort(all.begin(), all.end(), [](const Exercise& a, const Exercise& b) {
        return std::pair(a.lesson, a.number) < std::pair(b.lesson, b.number);
    });
    return all;
}

Result<Exercise> findExercise(const std::vector<Exercise>& all, int lesson, int number) {
    std::string known;
    for (const Exercise& e : all) {
        if (e.lesson == lesson && e.number == number) return e;
        known += (known.empty() ? "" : ", ") + e.id();
    }
    char id[32];
    std::snprintf(id, sizeof id, "%02d-%d", lesson, number);
    return Error{cat("no exercise ", id, "; these exist: ", known)};
}

fs::path studentRoot() {
    if (const char* dir = std::getenv("FXLAB_EXERCISES"); dir && *dir) return pathFromUtf8(dir);
    if (auto home = userHomeFolder()) return *home / "fxlab-exercises";
    return fs::current_path() / "fxlab-exercises";
}

fs::path studentFile(const Exercise& exercise, const fs::path& root) {
    return root / exercise.id() / exercise.file;
}

Result<fs::path> startExercise(const Exercise& exercise, const fs::path& root) {
    const fs::path target = studentFile(exercise, root);
    std::error_code ec;
    const auto status = fs::symlink_status(target, ec);
    if (fs::exists(status)) {
        if (fs::is_regular_file(fs::status(target, ec))) return target;  // their work stays as it is
        return Error{cat(target.string(), ": exists and is not a regular file; not replaced")};
    }
    auto starter = readFile(exercise.folder / exercise.file, file_limits::shader);
    if (!starter) return Error{starter.error()};
    if (Status written = writeFileAtomically(target, *starter); !written) return Error{written.error()};
    return target;
}

Result<ProgressBook> readProgress(const fs::path& root) {
    const fs::path file = root / "progress.json";
    std::error_code ec;
    if (!fs::exists(file, ec)) return ProgressBook{};
    auto text = readFile(file, file_limits::preset);
    if (!text) return Error{text.error()};
    ProgressBook book;
    try {
        const nlohmann::json json = nlohmann::json::parse(*text);
        if (!json.is_object()) return Error{cat(file.string(), ": expected an object of exercises")};
        for (const auto& [id, entry] : json.items()) {
            if (!entry.is_object() || !entry.contains("passed") || !entry["passed"].is_boolean())
                return Error{cat(file.string(), ": ", id, ".passed: expected true or false")};
            book[id] = {entry["passed"].get<bool>(), entry.value("message", std::string())};
        }
    } catch (const nlohmann::json::exception& e) {
        return Error{cat(file.string(), ": not JSON: ", e.what())};
    }
    return book;
}

Status recordProgress(const fs::path& root, const std::string& id, const ExerciseProgress& progress) {
    auto book = readProgress(root);
    if (!book) return Error{book.error()};
    (*book)[id] = progress;
    nlohmann::json json = nlohmann::json::object();
    for (const auto& [key, entry] : *book) json[key] = {{"passed", entry.passed}, {"message", entry.message}};
    return writeFileAtomically(root / "progress.json", dumpJson(json, 2) + "\n");
}

}  // namespace fx
