// Issue 40, defect 10: a capture killed with SIGKILL left NAME.tmpPID files that later runs never
// removed (only their own PID's). The next write of NAME removes those of dead processes, and nothing
// else.
#include <gtest/gtest.h>

#include <filesystem>

#include <sys/wait.h>
#include <unistd.h>

#include "base/file_io.hpp"

namespace fs = std::filesystem;

namespace {

// The id of a process that has ended (and been reaped).
pid_t deadProcess() {
    const pid_t child = ::fork();
    if (child == 0) ::_exit(0);
    int status = 0;
    ::waitpid(child, &status, 0);
    return child;
}

}  // namespace

TEST(StaleTemporaries, TheNextWriteRemovesTheTemporariesOfDeadWritersOnly) {
    const fs::path dir = fs::temp_directory_path() / ("fx_stale_tmp_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string dead = std::to_string(deadProcess());
    const std::string alive = std::to_string(::getppid());
    for (const std::string& name :
         {"final.png.tmp" + dead, "final.png.tmp" + alive, "final.png.tmpx" + dead, "notes.txt.tmp" + dead})
        ASSERT_TRUE(fx::writeFileAtomically(dir / name, std::string_view("half")));
    fs::create_directory(dir / ("final.png.tmp" + std::to_string(deadProcess())));  // a folder: kept
    fs::create_symlink(dir / ("notes.txt.tmp" + dead),
                       dir / ("final.png.tmp" + std::to_string(deadProcess())));

    ASSERT_TRUE(fx::writeFileAtomically(dir / "final.png", std::string_view("png")));
    EXPECT_FALSE(fs::exists(dir / ("final.png.tmp" + dead)));  // a dead writer's: gone
    EXPECT_TRUE(fs::exists(dir / ("final.png.tmp" + alive)));  // a live process's: its own
    EXPECT_TRUE(fs::exists(dir / ("final.png.tmpx" + dead)));  // not the pattern
    EXPECT_TRUE(fs::exists(dir / ("notes.txt.tmp" + dead)));   // another file's: left for its writer
    int kept = 0;
    for (const auto& entry : fs::directory_iterator(dir)) kept += entry.path().filename() != "final.png";
    EXPECT_EQ(kept, 5);  // everything but the one removed (the folder and the link among them)
    EXPECT_EQ(*fx::readTextFile(dir / "final.png"), "png");
    fs::remove_all(dir);
}
