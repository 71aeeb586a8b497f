// Every exercise graded as the check grades it: its solution passes, its starter fails, each typical
// wrong answer fails with the hint written for it, NaN is found and named, a compile error names the
// student's file and line, the student's file stands in for ours only while it is set, and a lesson
// whose student's file never compiled draws with ours until a save compiles.
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <optional>

#include "app/exercise_catalog.hpp"
#include "app/exercise_check.hpp"
#include "base/paths.hpp"
#include "gl/program.hpp"
#include "gl/shader_substitutes.hpp"
#include "gl_test.hpp"
#include "image/image_compare.hpp"

using namespace fx;
namespace fs = std::filesystem;

namespace {

std::vector<Exercise> shippedExercises() {
    auto all = loadExercises(exerciseRoot());
    EXPECT_TRUE(all.ok()) << all.error();
    return all ? *all : std::vector<Exercise>{};
}

class Exercises : public GlTest {
protected:
    fs::path dir;
    void SetUp() override {
        GlTest::SetUp();
        dir = fs::temp_directory_path() /
              ("fx_exercise_check_" +
               std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "_" +
               std::to_string(::getpid()));
        fs::create_directories(dir);
    }
    void TearDown() override {
        fs::remove_all(dir);
        GlTest::TearDown();
    }
    fs::path write(const std::string& name, const std::string& text) {
        std::ofstream(dir / name) << text;
        return dir / name;
    }
    // A fragment shader that includes the lesson's circle of confusion (exercise 09-1's file).
    fs::path cocProbe() {
        return write("probe.frag",
                     "#version 450 core\n#include \"effects/dof/coc.glsl\"\nout vec4 c;\n"
                     "void main() { c = vec4(signedCocPixels(0.5)); }\n");
    }
};

}  // namespace

TEST_F(Exercises, EverySolutionPassesEveryStarterFailsEveryWrongAnswerGetsItsHint) {
    const auto all = shippedExercises();
    ASSERT_GE(all.size(), 4u);
    for (const Exercise& e : all) {
        SCOPED_TRACE(e.id());
        const ExerciseVerdict solution = checkExercise(e, exerciseRoot() / "solutions" / e.id() / e.file);
        EXPECT_TRUE(solution.passed) << solution.message << "\n" << solution.error;
        EXPECT_LE(solution.measured, e.tolerance);

        const ExerciseVerdict starter = checkExercise(e, e.folder / e.file);
        EXPECT_FALSE(starter.passed) << "a starter must not hold the answer: " << starter.message;
        EXPECT_TRUE(starter.error.empty()) << "a starter builds: " << starter.error;
        EXPECT_FALSE(starter.hint.empty());

        int wrongAnswers = 0;
        for (const ExerciseHint& hint : e.hints) {
            if (hint.file.empty()) continue;
            ++wrongAnswers;
            SCOPED_TRACE(hint.file.filename().string());
            const ExerciseVerdict wrong = checkExercise(e, hint.file);
            EXPECT_FALSE(wrong.passed) << wrong.message;
            EXPECT_EQ(wrong.hint, hint.text) << wrong.message;
            if (hint.when == "invalid") continue;  // a scene that does not load: the loader's message
            // The message says what was measured against what.
            if (e.kind == "probe") {
                EXPECT_NE(wrong.message.find("against the reference"), std::string::npos) << wrong.message;
            }
            EXPECT_NE(wrong.message.find("needs <="), std::string::npos) << wrong.message;
        }
        EXPECT_GE(wrongAnswers, 1) << "every exercise has a typical wrong answer with its hint";
    }
}

TEST_F(Exercises, TheCentrePixelsNaNIsCountedAndNamed) {
    auto e = findExercise(shippedExercises(), 5, 1);
    ASSERT_TRUE(e.ok()) << e.error();
    const ExerciseVerdict starter = checkExercise(*e, e->folder / e->file);
    EXPECT_FALSE(starter.passed);
    // One centre pixel in each of the four cases.
    EXPECT_EQ(starter.nonFiniteTexels, 4);
    EXPECT_NE(starter.message.find("NaN or Inf (the first: pixel (32, 18) at 64x36)"), std::string::npos)
        << starter.message;
    EXPECT_NE(starter.hint.find("0 / 0"), std::string::npos) << starter.hint;
}

// The lesson's exercise views (F3) show the probe's results of the case the verdict is decided on: the
// pair of pictures kept in the verdict measures exactly what the verdict says, at the size it names.
TEST_F(Exercises, TheVerdictKeepsTheWorstCasesPictures) {
    int notTheFirstCase = 0;
    for (const Exercise& e : shippedExercises()) {
        if (e.kind != "probe") continue;
        std::vector<fs::path> answers = {e.folder / e.file, exerciseRoot() / "solutions" / e.id() / e.file};
        for (const ExerciseHint& hint : e.hints)
            if (!hint.file.empty()) answers.push_back(hint.file);
        for (const fs::path& answer : answers) {
            SCOPED_TRACE(e.id() + " " + answer.filename().string());
            const ExerciseVerdict v = checkExercise(e, answer);
            ASSERT_TRUE(v.error.empty()) << v.error;
            ASSERT_FALSE(v.studentImage.empty());
            ASSERT_EQ(v.studentImage.width, v.referenceImage.width);
            ASSERT_EQ(v.studentImage.height, v.referenceImage.height);
            const std::string size =
                std::to_string(v.studentImage.width) + "x" + std::to_string(v.studentImage.height);
            EXPECT_NE(v.message.find("worst at " + size + ","), std::string::npos) << v.message;
            auto difference = compare(v.studentImage, v.referenceImage);
            ASSERT_TRUE(difference.ok()) << difference.error();
            EXPECT_EQ(e.measure == "rmse" ? difference->rmse : difference->maxAbs, v.measured) << v.message;
            if (v.studentImage.width != e.cases.front().size.width ||
                v.studentImage.height != e.cases.front().size.height)
                ++notTheFirstCase;
        }
    }
    // Some answers are worst at a later size: the pictures follow the measure, not the first case.
    EXPECT_GT(notTheFirstCase, 0);
}

TEST_F(Exercises, ACompileErrorNamesTheStudentsFileAndLine) {
    auto e = findExercise(shippedExercises(), 8, 1);
    ASSERT_TRUE(e.ok()) << e.error();
    const fs::path student = write("cloud_step.glsl",
                                   "float stepOpacity(float a, float sigma, float len) {\n"
                                   "    return 1.0 - exp(-sigma * a * lenght);\n"
                                   "}\n");
    const ExerciseVerdict verdict = checkExercise(*e, student);
    EXPECT_FALSE(verdict.passed);
    const std::string place = student.string() + ":2:";
    EXPECT_NE(verdict.message.find(place), std::string::npos) << verdict.message;
    EXPECT_NE(verdict.message.find("lenght"), std::string::npos) << verdict.message;
    EXPECT_EQ(verdict.error.find("probe.frag:"), std::string::npos) << "nothing blamed on the probe:\n"
                                                                    << verdict.error;
    // No picture of theirs for the exercise views; the reference's of the first case stays.
    EXPECT_TRUE(verdict.studentImage.empty());
    EXPECT_EQ(verdict.referenceImage.width, e->cases.front().size.width);
    EXPECT_EQ(verdict.referenceImage.height, e->cases.front().size.height);

    const ExerciseVerdict missing = checkExercise(*e, dir / "never-started.glsl");
    EXPECT_FALSE(missing.passed);
    EXPECT_NE(missing.message.find("never-started.glsl: no such file"), std::string::npos) << missing.message;
}

TEST_F(Exercises, AStudentsFileStandsInForOursOnlyWhileItIsSet) {
    const fs::path student = write("coc.glsl", "float signedCocPixels(float d) { return 7.0; }\n");
    const fs::path frag = cocProbe();
    {
        gl::ShaderSubstitute substitute("effects/dof/coc.glsl", student);
        auto built = gl::Program::build({"common/fullscreen.vert", frag, {}, {}, "substituted"});
        ASSERT_TRUE(built.ok()) << built.error();
        EXPECT_NE(std::find(built->sourceFiles().begin(), built->sourceFiles().end(), student),
                  built->sourceFiles().end());
    }
    auto ours = gl::Program::build({"common/fullscreen.vert", frag, {}, {}, "ours"});
    ASSERT_TRUE(ours.ok()) << ours.error();
    EXPECT_EQ(std::find(ours->sourceFiles().begin(), ours->sourceFiles().end(), student),
              ours->sourceFiles().end());
}

TEST_F(Exercises, AStudentsFileThatNeverCompiledLeavesOursDrawingUntilASaveCompiles) {
    const fs::path student = write("coc.glsl", "float signedCocPixels(float d) {\n    return 7.0 * dd;\n}\n");
    const fs::path frag = cocProbe();
    gl::ShaderSubstitute substitute("effects/dof/coc.glsl", student);
    gl::ProgramRegistry registry;
    gl::ReloadableProgram program({"common/fullscreen.vert", frag, {}, {}, "exercise fallback"});
    // The lesson opens: ours draws, and the error is the student's, with their file and line.
    EXPECT_TRUE(program.usable()) << program.error();
    EXPECT_EQ(registry.firstUnusable(), std::nullopt);
    EXPECT_NE(program.error().find(student.string() + ":2:"), std::string::npos) << program.error();
    const auto& ours = program.program().sourceFiles();
    EXPECT_EQ(std::find(ours.begin(), ours.end(), student), ours.end()) << "built from our own file";
    EXPECT_EQ(gl::substitutedShaderFile(shaderDir() / "effects/dof/coc.glsl"), student)
        << "the substitute is back after the fallback";

    // The save that compiles takes over.
    std::ofstream(student) << "float signedCocPixels(float d) { return 7.0; }\n";
    fs::last_write_time(student, fs::last_write_time(student) + std::chrono::seconds(1));
    EXPECT_EQ(registry.reloadChanged(), 1);
    EXPECT_TRUE(program.error().empty()) << program.error();
    const auto& theirs = program.program().sourceFiles();
    EXPECT_NE(std::find(theirs.begin(), theirs.end(), student), theirs.end());
}
