// gl/context_guard.hpp: a GL object owner deletes its name only while a context is current on its
// thread, and counts the name instead when the context is gone (the Shader effects chapter's lifetime
// pitfall: program objects released after glfwTerminate call glDelete* without a context). No GL runs
// here: glDeleteProgram is pointed at a counter, so the test sees every delete the owners ask for.
#include <thread>
#include <type_traits>

#include <gtest/gtest.h>

#include "gl/context_guard.hpp"
#include "gl/object.hpp"
#include "gl/program.hpp"

namespace fx::gl {
namespace {

int deletes = 0;
GLuint lastDeleted = 0;
void GLAD_API_PTR countDelete(GLuint name) {
    ++deletes;
    lastDeleted = name;
}

// Owners of GL names cannot be copied: a copy would delete the same name twice, the second time
// perhaps a name the driver has handed to another object by then. They move instead.
static_assert(!std::is_copy_constructible_v<ProgramName> && !std::is_copy_assignable_v<ProgramName>);
static_assert(!std::is_copy_constructible_v<ReloadableProgram> &&
              !std::is_copy_assignable_v<ReloadableProgram>);
static_assert(std::is_nothrow_move_constructible_v<ProgramName>);

class ContextGuard : public ::testing::Test {
protected:
    PFNGLDELETEPROGRAMPROC saved = nullptr;
    void SetUp() override {
        saved = glad_glDeleteProgram;
        glad_glDeleteProgram = countDelete;
        deletes = 0;
        lastDeleted = 0;
    }
    void TearDown() override {
        glad_glDeleteProgram = saved;
        setContextAlive(false);
    }
};

TEST_F(ContextGuard, DeletesWhileTheContextIsCurrent) {
    setContextAlive(true);
    { ProgramName program(7); }
    EXPECT_EQ(deletes, 1);
    EXPECT_EQ(lastDeleted, 7u);
}

TEST_F(ContextGuard, CountsInsteadOfDeletingAfterTheContextIsGone) {
    setContextAlive(false);
    std::int64_t before = orphanedNames();
    { ProgramName program(7); }
    EXPECT_EQ(deletes, 0) << "no GL call without a context";
    EXPECT_EQ(orphanedNames(), before + 1);
}

TEST_F(ContextGuard, AMovedNameIsDeletedOnce) {
    setContextAlive(true);
    {
        ProgramName first(9);
        ProgramName second(std::move(first));
        ProgramName third;
        third = std::move(second);
        EXPECT_EQ(first.name(), 0u);
        EXPECT_EQ(third.name(), 9u);
    }
    EXPECT_EQ(deletes, 1);
}

TEST_F(ContextGuard, IsPerThread) {
    // A context is current on one thread; an owner released on another has none.
    setContextAlive(true);
    bool seenElsewhere = true;
    std::thread([&] { seenElsewhere = contextAlive(); }).join();
    EXPECT_TRUE(contextAlive());
    EXPECT_FALSE(seenElsewhere);
}

int creates = 0;
GLuint GLAD_API_PTR countCreateShader(GLenum) {
    ++creates;
    return 0;
}
GLuint GLAD_API_PTR countCreateProgram() {
    ++creates;
    return 0;
}

TEST_F(ContextGuard, AProgramBuiltBeforeTheContextIsAClearErrorAndCallsNoGl) {
    // The other end of the lifetime pitfall: a program made before the window (a global, a member built
    // too early) would call GL through glad's null pointers. The build refuses with a message naming
    // the program and the reason, and a ReloadableProgram made then is unusable and says why.
    setContextAlive(false);
    auto savedShader = glad_glCreateShader;
    auto savedProgram = glad_glCreateProgram;
    glad_glCreateShader = countCreateShader;
    glad_glCreateProgram = countCreateProgram;
    creates = 0;
    const ProgramSources sources{
        "common/fullscreen.vert", "effects/post/output_transform.frag", {}, {}, "early program"};
    auto built = Program::build(sources);
    ReloadableProgram reloadable(sources);
    glad_glCreateShader = savedShader;
    glad_glCreateProgram = savedProgram;

    ASSERT_FALSE(built.ok());
    EXPECT_NE(built.error().find("early program"), std::string::npos) << built.error();
    EXPECT_NE(built.error().find("no GL context is current"), std::string::npos) << built.error();
    EXPECT_FALSE(reloadable.usable());
    EXPECT_NE(reloadable.error().find("no GL context is current"), std::string::npos) << reloadable.error();
    EXPECT_EQ(creates, 0) << "GL was called without a context";
}

}  // namespace
}  // namespace fx::gl
