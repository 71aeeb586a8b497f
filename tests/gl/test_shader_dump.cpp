// --dump-shaders (gl/shader_dump.hpp): each stage the driver compiled is written as the very text it
// got (includes expanded, #defines in), named by the program's label, once per distinct text, with an
// index line that says whether the driver compiled or refused it and which files went in.
#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include "base/file_io.hpp"
#include "base/paths.hpp"
#include "effects/bloom/bloom_chain.hpp"
#include "gl/program.hpp"
#include "gl/shader_dump.hpp"
#include "gl/shader_source.hpp"
#include "gl_test.hpp"

using namespace fx;
namespace fs = std::filesystem;

namespace {

std::string fileText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream out;
    out << in.rdbuf();
    return out.str();
}

class ShaderDumpOnGl : public GlTest {
protected:
    void SetUp() override {
        GlTest::SetUp();
        folder = fs::temp_directory_path() / ("fxlab-shader-dump-" + std::to_string(::getpid()));
        fs::remove_all(folder);
        ASSERT_TRUE(gl::setShaderDumpFolder(folder));
    }
    void TearDown() override {
        EXPECT_TRUE(gl::setShaderDumpFolder({}));
        fs::remove_all(folder);
        GlTest::TearDown();
    }
    fs::path folder;
};

TEST_F(ShaderDumpOnGl, WritesTheTextTheDriverCompiledWithAnIndexLine) {
    const std::string defines = bloomShaderDefines() + shaderDefines({{"BLOOM_FILTERS", 1}});
    auto built = gl::Program::build({"common/fullscreen.vert",
                                     "effects/bloom/downsample.frag",
                                     {},
                                     defines,
                                     "test downsample (BLOOM_FILTERS 1)"});
    ASSERT_TRUE(built) << built.error();
    const fs::path frag = folder / "test_downsample_BLOOM_FILTERS_1.frag";
    ASSERT_TRUE(fs::exists(frag));
    ASSERT_TRUE(fs::exists(folder / "test_downsample_BLOOM_FILTERS_1.vert"));
    auto expanded =
        gl::expandShaderSource(shaderDir() / "effects/bloom/downsample.frag", shaderDir(), defines);
    ASSERT_TRUE(expanded) << expanded.error();
    EXPECT_EQ(fileText(frag), expanded->text);
    EXPECT_NE(fileText(frag).find("#define BLOOM_FILTERS 1"), std::string::npos);
    const std::string index = fileText(folder / "index.tsv");
    EXPECT_EQ(index.rfind("file\tstage\tdriver\tprogram\tsources\n", 0), 0u) << index;
    EXPECT_NE(
        index.find("\ntest_downsample_BLOOM_FILTERS_1.frag\tfrag\tcompiled\ttest downsample (BLOOM_FILTERS "
                   "1)\teffects/bloom/downsample.frag,effects/bloom/bloom_common.glsl,"
                   "effects/bloom/bloom_bindings.glsl\n"),
        std::string::npos)
        << index;

    // The same text again writes nothing new; another text under the same label gets "-2".
    ASSERT_TRUE(gl::Program::build({"common/fullscreen.vert",
                                    "effects/bloom/downsample.frag",
                                    {},
                                    defines,
                                    "test downsample (BLOOM_FILTERS 1)"}));
    EXPECT_FALSE(fs::exists(folder / "test_downsample_BLOOM_FILTERS_1-2.frag"));
    const std::string other = bloomShaderDefines() + shaderDefines({{"BLOOM_FILTERS", 0}});
    ASSERT_TRUE(gl::Program::build({"common/fullscreen.vert",
                                    "effects/bloom/downsample.frag",
                                    {},
                                    other,
                                    "test downsample (BLOOM_FILTERS 1)"}));
    EXPECT_TRUE(fs::exists(folder / "test_downsample_BLOOM_FILTERS_1-2.frag"));
    EXPECT_EQ(gl::shaderDumpFailures(), 0);
}

TEST_F(ShaderDumpOnGl, AStageTheDriverRefusesIsMarkedRefused) {
    const fs::path broken = folder / "source" / "broken.frag";
    ASSERT_TRUE(writeFileAtomically(
        broken, std::string("#version 450 core\nout vec4 c;\nvoid main() { c = 1.0 }\n")));
    auto built = gl::Program::build({"common/fullscreen.vert", broken, {}, {}, "broken on purpose"});
    EXPECT_FALSE(built);
    const std::string index = fileText(folder / "index.tsv");
    EXPECT_NE(index.find("\nbroken_on_purpose.frag\tfrag\trefused\tbroken on purpose\t"), std::string::npos)
        << index;
    EXPECT_NE(index.find("\nbroken_on_purpose.vert\tvert\tcompiled\t"), std::string::npos) << index;
}

TEST(ShaderDump, LabelsBecomeFileNames) {
    EXPECT_EQ(gl::shaderDumpBaseName("bloom upsample (BLOOM_FILTERS 1, BLOOM_WIDE 0)"),
              "bloom_upsample_BLOOM_FILTERS_1_BLOOM_WIDE_0");
    EXPECT_EQ(gl::shaderDumpBaseName("ui.texture view (linear -> sRGB)"), "ui_texture_view_linear_-_sRGB");
    EXPECT_EQ(gl::shaderDumpBaseName("../../etc/passwd"), "etc_passwd");
    EXPECT_EQ(gl::shaderDumpBaseName("***"), "program");
}

}  // namespace
