#include <gtest/gtest.h>

#include <filesystem>

#include <unistd.h>

#include "base/file_io.hpp"

namespace fs = std::filesystem;

TEST(FileIo, WritesAtomicallyAndReadsBack) {
    fs::path dir = fs::temp_directory_path() / ("fx_file_io_test_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::path file = dir / "nested" / "a.txt";
    ASSERT_TRUE(fx::writeFileAtomically(file, std::string_view("hello")).ok());
    auto text = fx::readTextFile(file);
    ASSERT_TRUE(text.ok());
    EXPECT_EQ(*text, "hello");
    // Nothing but the target is left in the folder.
    int entries = 0;
    for ([[maybe_unused]] auto& e : fs::directory_iterator(file.parent_path())) ++entries;
    EXPECT_EQ(entries, 1);
    fs::remove_all(dir);
}

TEST(FileIo, FailedWriteLeavesNothingAndNamesThePath) {
    fs::path dir = fs::temp_directory_path() / ("fx_file_io_test_ro_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    // A folder where the file should go: rename over it fails.
    fs::create_directories(dir / "target.txt" / "child");
    auto status = fx::writeFileAtomically(dir / "target.txt", std::string_view("x"));
    EXPECT_FALSE(status.ok());
    EXPECT_NE(status.error().find("target.txt"), std::string::npos);
    int entries = 0;
    for ([[maybe_unused]] auto& e : fs::directory_iterator(dir)) ++entries;
    EXPECT_EQ(entries, 1);
    fs::remove_all(dir);
}

TEST(FileIo, MissingFileNamesItsPath) {
    auto text = fx::readTextFile("/nonexistent/fx/shader.frag");
    ASSERT_FALSE(text.ok());
    EXPECT_NE(text.error().find("/nonexistent/fx/shader.frag"), std::string::npos);
}
