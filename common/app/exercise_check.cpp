#include "app/exercise_check.hpp"
#include "app/exercise_rules.hpp"
#include "base/json_text.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

#include <nlohmann/json.hpp>

#include "app/child_watchdog.hpp"
#include "app/exercise_scene_check.hpp"
#include "base/log.hpp"
#include "base/utf8_path.hpp"
#include "base/words.hpp"
#include "gl/debug_output.hpp"
#include "gl/framebuffer.hpp"
#include "gl/program.hpp"
#include "gl/readback.hpp"
#include "gl/shader_substitutes.hpp"
#include "gl/texture.hpp"
#include "image/image_compare.hpp"
#include "platform/context.hpp"

namespace fx {
namespace {

namespace fs = std::filesystem;

// The probe's result at every case's size, or why there is none.
struct ProbeRun {
    std::vector<FloatImage> images;
    std::string error;
};

Status setUniform(const gl::Program& program, const ExerciseUniform& u, Size2D size) {
    const GLint location = program.uniformLocation(u.name);
    if (location < 0) return Status::success();  // not used by this file: the compiler removed it
    std::vector<float> values = u.values;
    if (u.special == "size") values = {float(size.width), float(size.height)};
    // The middle pixel's centre: the pixel that sits exactly on it (a blur's centre, a NaN's home).
    if (u.special == "centre") values = {float(size.width / 2) + 0.5f, float(size.height / 2) + 0.5f};
    const GLuint index = glGetProgramResourceIndex(program.name(), GL_UNIFORM, u.name.c_str());
    const GLenum property = GL_TYPE;
    GLint type = 0;
    glGetProgramResourceiv(program.name(), GL_UNIFORM, index, 1, &property, 1, nullptr, &type);
    const auto count = values.size();
    auto wrongCount = [&](int expected) {
        return Error{cat("uniform ", u.name, " takes ", expected, " numbers; the exercise gives ", count)};
    };
    switch (type) {
        case GL_INT:
            if (count != 1) return wrongCount(1);
            glProgramUniform1i(program.name(), location, int(values[0]));
            return Status::success();
        case GL_FLOAT:
            if (count != 1) return wrongCount(1);
            glProgramUniform1fv(program.name(), location, 1, values.data());
            return Status::success();
        case GL_FLOAT_VEC2:
            if (count != 2) return wrongCount(2);
            glProgramUniform2fv(program.name(), location, 1, values.data());
            return Status::success();
        case GL_FLOAT_VEC3:
            if (count != 3) return wrongCount(3);
            glProgramUniform3fv(program.name(), location, 1, values.data());
            return Status::success();
        case GL_FLOAT_VEC4:
            if (count != 4) return wrongCount(4);
            glProgramUniform4fv(program.name(), location, 1, values.data());
            return Status::success();
        default:
            return Error{
                cat("uniform ", u.name, ": only int, float and vec2 to vec4 can be set by an exercise")};
    }
}

ProbeRun renderProbe(const Exercise& exercise, const fs::path& file) {
    gl::ShaderSubstitute substitute(exercise.replaces, file);
    auto program = gl::Program::build(
        {"common/fullscreen.vert", exercise.probe, {}, {}, cat("exercise ", exercise.id(), " probe")});
    if (!program) return {{}, program.error()};
    gl::DebugGroup group(cat("exercise ", exercise.id(), " probe"));
    gl::VertexArrayName vertices = gl::createVertexArray("exercise.probe.vertices");
    ProbeRun run;
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_CULL_FACE);
    glColorMaski(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    for (const ExerciseCase& c : exercise.cases) {
        gl::Texture target = gl::Texture::create2D(TextureFormat::RGBA32F, c.size.width, c.size.height, 1,
                                                   cat("exercise.", exercise.id(), ".result"));
        gl::Framebuffer framebuffer(cat("exercise.", exercise.id(), ".probe"));
        framebuffer.attachColor(0, target);
        framebuffer.setDrawBuffers(1);
        for (const ExerciseUniform& u : c.uniforms) {
            if (Status set = setUniform(*program, u, c.size); !set) return {{}, set.error()};
        }
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.name());
        glViewport(0, 0, c.size.width, c.size.height);
        glUseProgram(program->name());
        glBindVertexArray(vertices.name());
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glBindVertexArray(0);
        glUseProgram(0);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        run.images.push_back(gl::readTexture(target));
    }
    return run;
}

std::string sizeText(Size2D size) {
    return cat(size.width, "x", size.height);
}

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", value);
    return text;
}

struct Comparison {
    double measured = 0.0;
    std::size_t worst = 0;  // the case of `measured`
    Size2D worstAt;
    std::int64_t nonFinite = 0;
    std::string firstNonFinite;  // "pixel (16, 8) at 33x17"
};

Comparison compareRuns(const Exercise& exercise, const ProbeRun& student, const ProbeRun& reference) {
    Comparison out;
    for (std::size_t i = 0; i < exercise.cases.size(); ++i) {
        const FloatImage& mine = student.images[i];
        auto difference = compare(mine, reference.images[i]);
        const double value = !difference                  ? std::numeric_limits<double>::infinity()
                             : exercise.measure == "rmse" ? difference->rmse
                                                          : difference->maxAbs;
        if (value > out.measured || i == 0) {
            out.measured = value;
            out.worst = i;
            out.worstAt = exercise.cases[i].size;
        }
        for (int y = 0; y < mine.height; ++y) {
            for (int x = 0; x < mine.width; ++x) {
                bool finite = true;
                for (int ch = 0; ch < mine.channels; ++ch)
                    finite = finite && std::isfinite(mine.texel(x, y, ch));
                if (finite) continue;
                if (out.nonFinite++ == 0)
                    out.firstNonFinite =
                        say("check.pixelAt",
                            {{"x", cat(x)}, {"y", cat(y)}, {"size", sizeText(exercise.cases[i].size)}});
            }
        }
    }
    return out;
}

bool passes(const Exercise& exercise, const Comparison& c) {
    return c.nonFinite == 0 && c.measured <= exercise.tolerance;
}

std::string measureName(const std::string& measure) {
    return say(measure == "rmse" ? "check.rmse" : "check.maxAbs");
}

}  // namespace

ExerciseVerdict checkExercise(const Exercise& exercise, const fs::path& studentFile) {
    ExerciseVerdict verdict;
    verdict.measure = exercise.measure;
    verdict.tolerance = exercise.tolerance;
    std::error_code ec;
    if (auto refused = whyNotAStudentsFile(studentFile)) {
        verdict.error = verdict.message = *refused;
        return verdict;
    }
    if (!fs::is_regular_file(studentFile, ec)) {
        verdict.error = say("check.noFile", {{"file", studentFile.string()},
                                             {"lesson", cat(exercise.lesson)},
                                             {"number", cat(exercise.number)}});
        verdict.message = verdict.error;
        return verdict;
    }
    if (exercise.kind == "scene") return checkSceneExercise(exercise, studentFile);
    const ProbeRun reference = renderProbe(exercise, exercise.reference);
    if (!reference.error.empty()) {
        verdict.error = say("check.referenceBroken", {{"error", reference.error}});
        verdict.message = verdict.error;
        return verdict;
    }
    const ProbeRun student = renderProbe(exercise, studentFile);
    if (!student.error.empty()) {
        verdict.error = student.error;
        // The first error, which names the file and line; the whole log is in `error`.
        std::string first = student.error.substr(0, student.error.find('\n'));
        if (auto at = student.error.find(": error"); at != std::string::npos) {
            const auto begin = student.error.rfind('\n', at);
            first = student.error.substr(begin + 1, student.error.find('\n', at) - begin - 1);
        }
        verdict.message = say("check.didNotBuild", {{"error", first}});
        verdict.referenceImage = reference.images.front();
        return verdict;
    }
    const Comparison c = compareRuns(exercise, student, reference);
    verdict.passed = passes(exercise, c);
    verdict.measured = c.measured;
    verdict.nonFiniteTexels = c.nonFinite;
    verdict.studentImage = student.images[c.worst];
    verdict.referenceImage = reference.images[c.worst];
    verdict.message = say("check.measured", {{"measure", measureName(exercise.measure)},
                                             {"measured", number(c.measured)},
                                             {"measures", exercise.measures},
                                             {"tolerance", number(exercise.tolerance)},
                                             {"worst", sizeText(c.worstAt)},
                                             {"cases", cat(exercise.cases.size())}});
    if (c.nonFinite > 0)
        verdict.message += say(c.nonFinite == 1 ? "check.nonFiniteOne" : "check.nonFiniteMany",
                               {{"count", cat(c.nonFinite)}, {"first", c.firstNonFinite}});
    if (verdict.passed) return verdict;
    // The hint for the mistake this looks like: NaN first, then each typical wrong answer, then any.
    for (const ExerciseHint& hint : exercise.hints) {
        if (hint.when == "nonFinite" && c.nonFinite > 0) {
            verdict.hint = hint.text;
            return verdict;
        }
    }
    for (const ExerciseHint& hint : exercise.hints) {
        if (hint.when != "matches") continue;
        const ProbeRun wrong = renderProbe(exercise, hint.file);
        if (wrong.error.empty() && passes(exercise, compareRuns(exercise, student, wrong))) {
            verdict.hint = hint.text;
            return verdict;
        }
    }
    for (const ExerciseHint& hint : exercise.hints) {
        if (hint.when == "fails") verdict.hint = hint.text;
    }
    return verdict;
}

std::string verdictSummary(const ExerciseVerdict& v) {
    if (!v.error.empty()) return say("check.noMeasure");
    return say("check.summary", {{"verdict", say(v.passed ? "check.pass" : "check.fail")},
                                 {"measure", measureName(v.measure)},
                                 {"measured", number(v.measured)},
                                 {"tolerance", number(v.tolerance)}});
}

std::string verdictJson(const ExerciseVerdict& v) {
    nlohmann::json json = {{"passed", v.passed},
                           {"measure", v.measure},
                           {"tolerance", v.tolerance},
                           {"message", v.message},
                           {"hint", v.hint},
                           {"error", v.error},
                           {"nonFiniteTexels", v.nonFiniteTexels}};
    // JSON has no infinity: a measure that is not finite is null.
    json["measured"] = std::isfinite(v.measured) ? nlohmann::json(v.measured) : nlohmann::json(nullptr);
    return dumpJson(json);
}

Result<ExerciseVerdict> verdictFromJson(const std::string& text) {
    try {
        const nlohmann::json json = nlohmann::json::parse(text);
        ExerciseVerdict v;
        v.passed = json.at("passed").get<bool>();
        v.measure = json.at("measure").get<std::string>();
        v.tolerance = json.at("tolerance").get<double>();
        v.measured = json.at("measured").is_null() ? std::numeric_limits<double>::infinity()
                                                   : json.at("measured").get<double>();
        v.message = json.at("message").get<std::string>();
        v.hint = json.at("hint").get<std::string>();
        v.error = json.at("error").get<std::string>();
        v.nonFiniteTexels = json.at("nonFiniteTexels").get<std::int64_t>();
        return v;
    } catch (const nlohmann::json::exception& e) {
        return Error{cat("not a verdict: ", e.what())};
    }
}

void registerExerciseCheckWork() {
    registerChildWork(kExerciseCheckWork, [](const std::vector<std::string>& arguments) {
        // The child: its own headless context, the check, the verdict as text.
        ExerciseVerdict verdict;
        if (arguments.size() != 2) {
            verdict.error = verdict.message = "the check's child was started without an exercise and a file";
            return verdictJson(verdict);
        }
        auto exercise = loadExercise(pathFromUtf8(arguments[0]));
        if (!exercise) {
            verdict.error = verdict.message = exercise.error();
            return verdictJson(verdict);
        }
        ContextOptions options;
        options.size = {16, 16};
        options.title = cat("fxlab check ", exercise->id());
        if (auto context = createHeadlessContext(options))
            verdict = checkExercise(*exercise, pathFromUtf8(arguments[1]));
        else
            verdict.error = verdict.message = cat("no GL context for the check: ", context.error());
        return verdictJson(verdict);
    });
}

ExerciseVerdict checkExerciseGuarded(const Exercise& exercise, const fs::path& studentFile, double seconds) {
    if (auto notOwn = whyNotTheStudentsOwn(studentFile)) {
        ExerciseVerdict refused;
        refused.measure = exercise.measure;
        refused.tolerance = exercise.tolerance;
        refused.error = refused.message = *notOwn;
        return refused;
    }
    registerExerciseCheckWork();
    const ChildOutcome outcome =
        runInChildWithin(kExerciseCheckWork, {exercise.folder.string(), studentFile.string()}, seconds);
    ExerciseVerdict failed;
    failed.measure = exercise.measure;
    failed.tolerance = exercise.tolerance;
    switch (outcome.kind) {
        case ChildOutcome::Kind::finished:
            if (auto verdict = verdictFromJson(outcome.answer)) return *verdict;
            failed.error = "the check ended without a verdict";
            break;
        case ChildOutcome::Kind::timedOut:
            failed.error = exercise.kind == "scene"
                               ? cat("the check did not finish within ", number(seconds),
                                     " s: your scene asks for more particles than the check can simulate")
                               : cat("the check did not finish within ", number(seconds),
                                     " s: does a loop in your shader never end?");
            break;
        case ChildOutcome::Kind::crashed:
            failed.error = cat("the check crashed (", outcome.reason, ")");
            break;
        case ChildOutcome::Kind::notStarted:
            failed.error = cat("the check could not start: ", outcome.reason);
            break;
    }
    failed.message = failed.error;
    return failed;
}

}  // namespace fx
