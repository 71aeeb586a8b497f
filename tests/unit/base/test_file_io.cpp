#include <gtest/gtest.h>

#include <filesystem>

#include <sys/stat.h>
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

namespace {

// A fresh folder under /tmp for one test, removed afterwards.
struct TempFolder {
    fs::path path;
    explicit TempFolder(const std::string& name)
        : path(fs::temp_directory_path() / (name + "_" + std::to_string(::getpid()))) {
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TempFolder() { fs::remove_all(path); }
};

}  // namespace

TEST(FileIo, WritingThroughASymlinkReplacesItsTargetAndKeepsTheLink) {
    TempFolder dir("fx_file_io_link");
    fs::path target = dir.path / "real.json";
    ASSERT_TRUE(fx::writeFileAtomically(target, std::string_view("old")).ok());
    fs::create_symlink(target, dir.path / "link.json");
    ASSERT_TRUE(fx::writeFileAtomically(dir.path / "link.json", std::string_view("new")).ok());
    EXPECT_TRUE(fs::is_symlink(dir.path / "link.json"));
    EXPECT_EQ(*fx::readTextFile(target), "new");
}

TEST(FileIo, ADeviceIsWrittenThroughNotReplaced) {
    // /dev/null stays a character device; before the fix it became a regular file (as root) or the
    // write failed trying to put a temporary file in /dev.
    auto status = fx::writeFileAtomically(fs::path("/dev/null"), std::string_view("{}"));
    EXPECT_TRUE(status.ok()) << status.error();
    EXPECT_TRUE(fs::is_character_file("/dev/null"));
    // /dev/full takes no bytes: the device's own reason comes back.
    auto full = fx::writeFileAtomically(fs::path("/dev/full"), std::string_view("{}"));
    ASSERT_FALSE(full.ok());
    EXPECT_NE(full.error().find("No space left on device"), std::string::npos) << full.error();
    EXPECT_TRUE(fs::is_character_file("/dev/full"));
}

TEST(FileIo, AFolderIsAClearErrorNotSuccess) {
    TempFolder dir("fx_file_io_folder");
    auto status = fx::writeFileAtomically(dir.path, std::string_view("x"));
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.error().find("is a folder"), std::string::npos) << status.error();
    EXPECT_EQ(status.error().find("Success"), std::string::npos) << status.error();
}

TEST(FileIo, AFifoWithoutReaderIsRefusedNotWaitedFor) {
    TempFolder dir("fx_file_io_fifo");
    fs::path fifo = dir.path / "pipe";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    auto status = fx::writeFileAtomically(fifo, std::string_view("x"));
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.error().find("nothing is reading it"), std::string::npos) << status.error();
    EXPECT_TRUE(fs::is_fifo(fifo));
    auto read = fx::readTextFile(fifo);  // would block forever without O_NONBLOCK
    ASSERT_FALSE(read.ok());
    EXPECT_NE(read.error().find("FIFO"), std::string::npos) << read.error();
}

TEST(FileIo, ReadsOnlyRegularFilesWithinTheLimit) {
    TempFolder dir("fx_file_io_limits");
    auto folder = fx::readFile(dir.path, fx::file_limits::scene);
    ASSERT_FALSE(folder.ok());
    EXPECT_NE(folder.error().find("is a folder, not a scene file"), std::string::npos) << folder.error();
    // /dev/zero through a link: refused at once, nothing allocated.
    fs::create_symlink("/dev/zero", dir.path / "zero.json");
    auto zero = fx::readFile(dir.path / "zero.json", fx::file_limits::scene);
    ASSERT_FALSE(zero.ok());
    EXPECT_NE(zero.error().find("character device"), std::string::npos) << zero.error();
    // A file over its kind's limit says which limit.
    ASSERT_TRUE(fx::writeFileAtomically(dir.path / "big.json", std::string(2 * 1024 * 1024 + 1, ' ')).ok());
    auto big = fx::readFile(dir.path / "big.json", fx::FileLimit{"preset", 2 * 1024 * 1024});
    ASSERT_FALSE(big.ok());
    EXPECT_NE(big.error().find("over the limit for a preset (2 MiB)"), std::string::npos) << big.error();
    EXPECT_TRUE(fx::readFile(dir.path / "big.json", fx::FileLimit{"preset", 2 * 1024 * 1024 + 1}).ok());
}

TEST(FileIo, AFileInProcThatSaysSizeZeroIsReadWhole) {
    auto text = fx::readFile("/proc/self/status", fx::file_limits::text);
    ASSERT_TRUE(text.ok()) << text.error();
    EXPECT_NE(text->find("Name:"), std::string::npos);
    auto small = fx::readFile("/proc/self/status", fx::FileLimit{"status", 16});
    EXPECT_FALSE(small.ok());
}
