// #include expansion and compiler-log mapping, without a GL context.
#include <gtest/gtest.h>

#include <map>
#include <utility>
#include <vector>

#include <unistd.h>

#include "base/paths.hpp"
#include "gl/shader_source.hpp"

using fx::gl::expandShaderSource;
using fx::gl::mapCompilerLog;
namespace fs = std::filesystem;

namespace {

// Real temporary files: the expander resolves includes by looking at the file system.
struct Files {
    // One folder per test and process: ctest runs these tests in parallel.
    fs::path root =
        fs::temp_directory_path() /
        ("fx_shader_source_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) +
         "_" + std::to_string(::getpid()));
    Files() {
        fs::remove_all(root);
        fs::create_directories(root / "common");
    }
    ~Files() { fs::remove_all(root); }
    fs::path add(const std::string& name, const std::string& text) {
        fs::path p = root / name;
        fs::create_directories(p.parent_path());
        FILE* f = std::fopen(p.c_str(), "wb");
        std::fwrite(text.data(), 1, text.size(), f);
        std::fclose(f);
        return p;
    }
};

}  // namespace

TEST(ShaderSource, IncludesAreExpandedWithLineDirectives) {
    Files files;
    files.add("common/a.glsl", "float a() { return 1.0; }\n");
    auto main = files.add("main.frag", "#version 450 core\n#include \"common/a.glsl\"\nvoid main() {}\n");
    auto source = expandShaderSource(main, files.root);
    ASSERT_TRUE(source.ok()) << source.error();
    EXPECT_EQ(source->text,
              "#version 450 core\n#line 2 0\n#line 100001 1\nfloat a() { return 1.0; }\n#line 3 0\nvoid "
              "main() {}\n");
    ASSERT_EQ(source->fileNames.size(), 2u);
    EXPECT_EQ(source->fileNames[0], "main.frag");
    EXPECT_EQ(source->fileNames[1], "common/a.glsl");
    EXPECT_EQ(source->files.size(), 2u);
}

TEST(ShaderSource, DefinesGoRightAfterVersion) {
    Files files;
    auto main = files.add("d.frag", "#version 450 core\nvoid main() {}\n");
    auto source = expandShaderSource(main, files.root, "#define TAPS 16");
    ASSERT_TRUE(source.ok());
    EXPECT_EQ(source->text, "#version 450 core\n#define TAPS 16\n#line 2 0\nvoid main() {}\n");
}

TEST(ShaderSource, AFileIsIncludedOnce) {
    Files files;
    files.add("common/once.glsl", "float once;\n");
    files.add("common/b.glsl", "#include \"once.glsl\"\nfloat b;\n");
    auto main =
        files.add("m.frag", "#version 450 core\n#include \"common/once.glsl\"\n#include \"common/b.glsl\"\n");
    auto source = expandShaderSource(main, files.root);
    ASSERT_TRUE(source.ok()) << source.error();
    EXPECT_EQ(source->fileNames.size(), 3u);
    std::size_t first = source->text.find("float once;");
    EXPECT_NE(first, std::string::npos);
    EXPECT_EQ(source->text.find("float once;", first + 1), std::string::npos);
}

TEST(ShaderSource, ACycleIsAnError) {
    Files files;
    files.add("x.glsl", "#include \"y.glsl\"\n");
    files.add("y.glsl", "#include \"x.glsl\"\n");
    auto main = files.add("c.frag", "#version 450 core\n#include \"x.glsl\"\n");
    auto source = expandShaderSource(main, files.root);
    ASSERT_FALSE(source.ok());
    EXPECT_NE(source.error().find("#include cycle: c.frag -> x.glsl -> y.glsl -> x.glsl"), std::string::npos)
        << source.error();
}

TEST(ShaderSource, AMissingIncludeNamesTheFileAndLineOfTheDirective) {
    Files files;
    auto main = files.add("miss.frag", "#version 450 core\n\n#include \"nowhere.glsl\"\n");
    auto source = expandShaderSource(main, files.root);
    ASSERT_FALSE(source.ok());
    EXPECT_NE(source.error().find("miss.frag:3: cannot find included file \"nowhere.glsl\""),
              std::string::npos)
        << source.error();
}

TEST(ShaderSource, MissingVersionIsAnError) {
    Files files;
    auto main = files.add("nov.frag", "void main() {}\n");
    auto source = expandShaderSource(main, files.root);
    ASSERT_FALSE(source.ok());
    EXPECT_NE(source.error().find("#version"), std::string::npos);
}

TEST(ShaderSource, CompilerLogsOfThreeVendorsAreMapped) {
    std::vector<std::string> names = {"main.frag", "common/a.glsl"};
    EXPECT_EQ(mapCompilerLog("0:12(5): error: `x' undeclared\n", names),
              "main.frag:12:5: error: `x' undeclared\n");
    EXPECT_EQ(mapCompilerLog("1(3) : error C1008: undefined variable \"y\"\n", names),
              "common/a.glsl:3: error C1008: undefined variable \"y\"\n");
    EXPECT_EQ(mapCompilerLog("ERROR: 1:7: 'z' : undeclared identifier\n", names),
              "common/a.glsl:7: ERROR: 'z' : undeclared identifier\n");
    EXPECT_EQ(mapCompilerLog("7:1(1): error: odd\n", names), "<source 7>:1:1: error: odd\n");
}

// Mesa reports an error inside an expression of an included file with source-string number 0 and the
// right line; the line's block (100000 per file) still names the included file.
TEST(ShaderSource, LogLinesNameTheIncludedFileByTheirBlock) {
    std::vector<std::string> names = {"probe.frag", "student.glsl"};
    EXPECT_EQ(mapCompilerLog("0:100002(42): error: `stepLengt' undeclared\n", names),
              "student.glsl:2:42: error: `stepLengt' undeclared\n");
    EXPECT_EQ(mapCompilerLog("1(100002) : error C1008: undefined variable\n", names),
              "student.glsl:2: error C1008: undefined variable\n");
}

// A folder given as a shader used to read as an empty file and fail with "the first directive must be
// #version"; the reader now says what the path is.
TEST(ShaderSource, AFolderIsNamedAsAFolderNotAMissingVersion) {
    Files files;
    fs::create_directories(files.root / "lit.frag");
    auto expanded = expandShaderSource(files.root / "lit.frag", files.root);
    ASSERT_FALSE(expanded.ok());
    EXPECT_NE(expanded.error().find("is a folder, not a shader"), std::string::npos) << expanded.error();
    EXPECT_EQ(expanded.error().find("#version"), std::string::npos) << expanded.error();
}

// Issue 40, defects 5 and 6: an #include read any file (/etc/passwd, /proc/self/environ), and a
// student's one-line #include of the solution passed the check.
TEST(ShaderSource, AnIncludeStaysBesideTheFileInTheShadersOrInExercises) {
    Files files;
    const fs::path solution =
        fx::projectRoot() / "exercises" / "solutions" / "05-1" / "radial_blur_offset.glsl";
    ASSERT_TRUE(fs::is_regular_file(solution));
    files.add("elsewhere/secret.glsl", "float secret;\n");
    fs::create_directories(files.root / "student");
    fs::create_symlink(solution, files.root / "student" / "linked.glsl");
    const std::vector<std::pair<std::string, std::string>> refused = {
        {"\"../elsewhere/secret.glsl\"", "outside the including file's folder"},
        {"\"/etc/passwd\"", "resolves to /etc/passwd, which is outside"},
        {"\"" + solution.string() + "\"", "inside the exercises' answers"},
        {"\"../../../../../../../../../../../.." + solution.string() + "\"", "inside the exercises' answers"},
        {"\"linked.glsl\"", "inside the exercises' answers"},  // a link beside the file to the answer
    };
    for (const auto& [name, reason] : refused) {
        auto student =
            files.add("student/radial_blur_offset.glsl", "#version 450 core\n\n#include " + name + "\n");
        auto source = expandShaderSource(student, fx::shaderDir());
        ASSERT_FALSE(source.ok()) << name;
        EXPECT_NE(source.error().find("radial_blur_offset.glsl:3: #include \""), std::string::npos)
            << source.error();
        EXPECT_NE(source.error().find(reason), std::string::npos) << source.error();
        EXPECT_NE(source.error().find("never an exercise's answers"), std::string::npos) << source.error();
    }
    // Beside the file and in shaders/: as before.
    files.add("student/helper.glsl", "float helper;\n");
    auto fine = files.add(
        "student/ok.frag",
        "#version 450 core\n#include \"helper.glsl\"\n#include \"effects/post/post_bindings.glsl\"\n");
    auto source = expandShaderSource(fine, fx::shaderDir());
    EXPECT_TRUE(source.ok()) << source.error();
}

// Issue 40, defect 8: a 2 KB macro bomb killed the lesson inside Mesa's compiler (SIGSEGV at 5.4 GB).
TEST(ShaderSource, AMacroBombIsRefusedBeforeTheCompilerSeesIt) {
    Files files;
    std::string bomb = "#version 450 core\n#define B0 1.0\n";
    for (int n = 1; n <= 23; ++n)
        bomb += "#define B" + std::to_string(n) + " (B" + std::to_string(n - 1) + "+B" +
                std::to_string(n - 1) + ")\n";
    bomb += "out vec4 c;\nvoid main() { c = vec4(B23); }\n";
    auto source = expandShaderSource(files.add("bomb.frag", bomb), files.root);
    ASSERT_FALSE(source.ok());
    EXPECT_NE(source.error().find("bomb.frag:"), std::string::npos) << source.error();
    EXPECT_NE(source.error().find("expands to"), std::string::npos) << source.error();
    EXPECT_NE(source.error().find("the shader is not compiled"), std::string::npos) << source.error();

    // Defined in reverse order, or across an include: counted the same.
    std::string reversed = "#version 450 core\n#include \"half.glsl\"\n";
    for (int n = 23; n >= 12; --n)
        reversed += "#define B" + std::to_string(n) + " (B" + std::to_string(n - 1) + "+B" +
                    std::to_string(n - 1) + ")\n";
    std::string half = "#define B0 1.0\n";
    for (int n = 1; n < 12; ++n)
        half += "#define B" + std::to_string(n) + " B" + std::to_string(n - 1) + " B" +
                std::to_string(n - 1) + "\n";
    files.add("half.glsl", half);
    EXPECT_FALSE(expandShaderSource(files.add("reversed.frag", reversed), files.root).ok());

    // Ordinary macros, a self-reference and the shipped shaders: fine.
    auto fine = expandShaderSource(
        files.add("fine.frag",
                  "#version 450 core\n#define TAPS 16\n#define TWICE (TAPS + TAPS)\n#define X X\n"),
        files.root);
    EXPECT_TRUE(fine.ok()) << fine.error();
}
