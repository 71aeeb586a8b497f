// Program objects: compile errors name the real file and line (also in included files), link errors
// are reported, a failed reload keeps the last good program.
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "gl/framebuffer.hpp"
#include "gl/program.hpp"
#include "gl_test.hpp"

using namespace fx;
namespace fs = std::filesystem;

class Programs : public GlTest {
protected:
    fs::path dir;
    void SetUp() override {
        GlTest::SetUp();
        dir = fs::temp_directory_path() /
              ("fx_programs_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) +
               "_" + std::to_string(::getpid()));
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override {
        fs::remove_all(dir);
        GlTest::TearDown();
    }
    fs::path write(const std::string& name, const std::string& text) {
        fs::path p = dir / name;
        std::ofstream(p) << text;
        return p;
    }
    gl::ProgramSources sources(const fs::path& vs, const fs::path& fs_) { return {vs, fs_, {}, {}, "test"}; }
    fs::path goodVertex() {
        return write(
            "ok.vert",
            "#version 450 core\nlayout(location=0) in vec3 p;\nvoid main(){ gl_Position = vec4(p,1); }\n");
    }
};

TEST_F(Programs, BuildsAndListsActiveUniforms) {
    auto frag = write("ok.frag",
                      "#version 450 core\nuniform vec4 tint;\nuniform float unused;\nout vec4 c;\nvoid "
                      "main(){ c = tint; }\n");
    auto program = gl::Program::build(sources(goodVertex(), frag));
    ASSERT_TRUE(program.ok()) << program.error();
    EXPECT_TRUE(program->hasUniform("tint"));
    // Declared but unused: the compiler removes it, so the program does not have it (chapter 2.5).
    EXPECT_FALSE(program->hasUniform("unused"));
}

TEST_F(Programs, CompileErrorNamesFileAndLine) {
    auto frag = write("broken.frag",
                      "#version 450 core\nout vec4 c;\n\nvoid main(){\n  c = vec4(1) * undefinedThing;\n}\n");
    auto program = gl::Program::build(sources(goodVertex(), frag));
    ASSERT_FALSE(program.ok());
    EXPECT_NE(program.error().find("broken.frag:5"), std::string::npos) << program.error();
    EXPECT_NE(program.error().find("undefinedThing"), std::string::npos) << program.error();
}

TEST_F(Programs, CompileErrorInsideIncludeNamesTheIncludedFile) {
    write("helpers.glsl",
          "// helpers\nfloat halve(float x) { return x * 0.5; }\nfloat bad() { return nope; }\n");
    auto frag = write(
        "user.frag",
        "#version 450 core\n#include \"helpers.glsl\"\nout vec4 c;\nvoid main(){ c = vec4(halve(1.0)); }\n");
    auto program = gl::Program::build(sources(goodVertex(), frag));
    ASSERT_FALSE(program.ok());
    EXPECT_NE(program.error().find("helpers.glsl:3"), std::string::npos) << program.error();
}

TEST_F(Programs, ErrorAfterAnIncludeMapsBackToTheIncluder) {
    write("one.glsl", "float one() { return 1.0; }\n");
    auto frag = write("after.frag",
                      "#version 450 core\n#include \"one.glsl\"\nout vec4 c;\nvoid main(){\n  c = "
                      "vec4(one()) + missing;\n}\n");
    auto program = gl::Program::build(sources(goodVertex(), frag));
    ASSERT_FALSE(program.ok());
    EXPECT_NE(program.error().find("after.frag:5"), std::string::npos) << program.error();
}

TEST_F(Programs, MissingFileIsNamed) {
    auto program = gl::Program::build(sources(goodVertex(), dir / "nowhere.frag"));
    ASSERT_FALSE(program.ok());
    EXPECT_NE(program.error().find("nowhere.frag"), std::string::npos) << program.error();
}

TEST_F(Programs, LinkErrorIsReported) {
    // The fragment stage reads a varying the vertex stage never writes.
    auto frag = write(
        "link.frag",
        "#version 450 core\nin vec3 notWritten;\nout vec4 c;\nvoid main(){ c = vec4(notWritten,1); }\n");
    auto vert = write("link.vert", "#version 450 core\nvoid main(){ gl_Position = vec4(0); }\n");
    auto program = gl::Program::build(sources(vert, frag));
    ASSERT_FALSE(program.ok());
    EXPECT_NE(program.error().find("link failed"), std::string::npos) << program.error();
}

TEST_F(Programs, FailedReloadKeepsTheLastGoodProgram) {
    auto frag = write("live.frag", "#version 450 core\nout vec4 c;\nvoid main(){ c = vec4(1); }\n");
    gl::ReloadableProgram live(sources(goodVertex(), frag));
    ASSERT_TRUE(live.usable()) << live.error();
    GLuint good = live.name();

    write("live.frag", "#version 450 core\nout vec4 c;\nvoid main(){ c = vec4(1) }\n");  // missing ';'
    EXPECT_FALSE(live.reload().ok());
    EXPECT_EQ(live.name(), good);
    EXPECT_TRUE(glIsProgram(good));
    EXPECT_NE(live.error().find("live.frag:3"), std::string::npos) << live.error();

    write("live.frag", "#version 450 core\nout vec4 c;\nvoid main(){ c = vec4(0.5); }\n");
    EXPECT_TRUE(live.reload().ok());
    EXPECT_TRUE(live.error().empty());
    EXPECT_EQ(live.generation(), 2);
}

TEST_F(Programs, ReloadIfChangedNoticesAnEditedInclude) {
    auto inc = write("value.glsl", "float value() { return 1.0; }\n");
    auto frag =
        write("watch.frag",
              "#version 450 core\n#include \"value.glsl\"\nout vec4 c;\nvoid main(){ c = vec4(value()); }\n");
    gl::ReloadableProgram live(sources(goodVertex(), frag));
    ASSERT_TRUE(live.usable());
    EXPECT_FALSE(live.reloadIfChanged());
    std::ofstream(inc) << "float value() { return 2.0; }\n";
    fs::last_write_time(inc, fs::last_write_time(inc) + std::chrono::seconds(2));
    EXPECT_TRUE(live.reloadIfChanged());
    EXPECT_EQ(live.generation(), 2);
}

class Framebuffers : public GlTest {};

TEST_F(Framebuffers, IncompleteFramebufferIsReportedByName) {
    gl::Framebuffer fbo("bloom.down[3]");
    // A depth texture on a colour attachment point is an incomplete attachment.
    auto depth = gl::Texture::create2D(TextureFormat::Depth32F, 4, 4, 1, "depth");
    fbo.attachColor(0, depth);
    fbo.setDrawBuffers(1);
    auto status = fbo.checkComplete();
    ASSERT_FALSE(status.ok());
    EXPECT_EQ(status.error(), "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT on bloom.down[3]");
}

TEST_F(Framebuffers, EmptyFramebufferIsMissingAttachment) {
    gl::Framebuffer fbo("nothing attached");
    auto status = fbo.checkComplete();
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.error().find("GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT"), std::string::npos);
}

TEST_F(Framebuffers, CompleteFramebufferPasses) {
    gl::Framebuffer fbo("scene");
    auto color = gl::Texture::create2D(TextureFormat::RGBA16F, 3, 2, 1, "scene.color");
    auto depth = gl::Texture::create2D(TextureFormat::Depth32F, 3, 2, 1, "scene.depth");
    fbo.attachColor(0, color);
    fbo.attachDepth(depth);
    fbo.setDrawBuffers(1);
    EXPECT_TRUE(fbo.checkComplete().ok());
}

// The registry collects programs where they are built, follows them when they move, forgets them when
// they are destroyed, and answers for all of them: what the runner does instead of a lesson's list.
TEST_F(Programs, RegistryCollectsProgramsWhereverTheyAreBuiltAndFollowsMoves) {
    auto vert = goodVertex();
    auto frag = write("ok.frag", "#version 450 core\nout vec4 c;\nvoid main(){ c = vec4(1); }\n");
    auto broken = write("broken.frag", "#version 450 core\nout vec4 c;\nvoid main(){ c = nope; }\n");
    gl::ReloadableProgram outside(sources(vert, frag));  // built before: not in the registry
    gl::ProgramRegistry registry;
    EXPECT_EQ(gl::ProgramRegistry::open(), &registry);
    gl::ReloadableProgram kept;
    {
        gl::ReloadableProgram made(sources(vert, frag));
        kept = std::move(made);  // as an effect's create() result moves into a lesson member
    }
    EXPECT_EQ(registry.size(), 1u);
    EXPECT_FALSE(registry.firstUnusable());
    EXPECT_TRUE(registry.errors().empty());
    {
        gl::ReloadableProgram failing(sources(vert, broken));
        EXPECT_EQ(registry.size(), 2u);
        ASSERT_TRUE(registry.firstUnusable());
        EXPECT_NE(registry.firstUnusable()->find("broken.frag"), std::string::npos)
            << *registry.firstUnusable();
        EXPECT_EQ(registry.errors().size(), 1u);
    }
    EXPECT_EQ(registry.size(), 1u) << "a destroyed program leaves the registry";
    EXPECT_FALSE(registry.firstUnusable());
    // A reload through the registry reaches the moved program.
    int before = kept.generation();
    registry.reloadAll();
    EXPECT_EQ(kept.generation(), before + 1);
    EXPECT_EQ(outside.generation(), 1) << "a program built before the registry opened is not in it";
}

TEST_F(Programs, RegistriesNestAndCloseInOrder) {
    gl::ProgramRegistry outer;
    {
        gl::ProgramRegistry inner;
        EXPECT_EQ(gl::ProgramRegistry::open(), &inner);
    }
    EXPECT_EQ(gl::ProgramRegistry::open(), &outer);
}
