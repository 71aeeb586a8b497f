#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <iterator>

#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
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

// The one rule for every file written (docs/reliability.md): never through a link, never into a
// device, a FIFO, a socket or a folder, never outside the chosen folder.

TEST(FileIo, AWorkingSymlinkAtTheTargetIsRefusedAndNeitherItNorItsTargetChanges) {
    TempFolder dir("fx_file_io_link");
    TempFolder elsewhere("fx_file_io_link_elsewhere");
    fs::path target = elsewhere.path / "real.json";
    ASSERT_TRUE(fx::writeFileAtomically(target, std::string_view("old")).ok());
    fs::create_symlink(target, dir.path / "link.json");
    auto status = fx::writeFileAtomically(dir.path / "link.json", std::string_view("new"));
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.error().find("link.json: is a symbolic link"), std::string::npos) << status.error();
    EXPECT_TRUE(fs::is_symlink(dir.path / "link.json"));
    EXPECT_EQ(*fx::readTextFile(target), "old");
    EXPECT_EQ(std::distance(fs::directory_iterator(dir.path), fs::directory_iterator()), 1);
}

TEST(FileIo, ADanglingSymlinkIsRefusedAndStaysALink) {
    TempFolder dir("fx_file_io_dangling");
    TempFolder elsewhere("fx_file_io_dangling_elsewhere");
    fs::path missing = elsewhere.path / "made.json";
    fs::create_symlink(missing, dir.path / "report.json");
    auto status = fx::writeFileAtomically(dir.path / "report.json", std::string_view("{}"));
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.error().find("is a symbolic link"), std::string::npos) << status.error();
    EXPECT_TRUE(fs::is_symlink(dir.path / "report.json"));
    EXPECT_FALSE(fs::exists(missing));
}

TEST(FileIo, ADeviceIsRefusedAndStaysADevice) {
    // /dev/null would take the bytes and /dev/full would fail; neither is a file fxlab may write.
    for (const char* device : {"/dev/null", "/dev/full"}) {
        auto status = fx::writeFileAtomically(fs::path(device), std::string_view("{}"));
        ASSERT_FALSE(status.ok()) << device;
        EXPECT_NE(status.error().find("is a character device"), std::string::npos) << status.error();
        EXPECT_TRUE(fs::is_character_file(device));
    }
}

TEST(FileIo, AFolderIsAClearErrorNotSuccess) {
    TempFolder dir("fx_file_io_folder");
    auto status = fx::writeFileAtomically(dir.path, std::string_view("x"));
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.error().find("is a folder"), std::string::npos) << status.error();
    EXPECT_EQ(status.error().find("Success"), std::string::npos) << status.error();
}

TEST(FileIo, AFifoIsRefusedNotWrittenNorWaitedFor) {
    TempFolder dir("fx_file_io_fifo");
    fs::path fifo = dir.path / "pipe";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    auto status = fx::writeFileAtomically(fifo, std::string_view("x"));
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.error().find("is a FIFO"), std::string::npos) << status.error();
    EXPECT_TRUE(fs::is_fifo(fifo));
    auto read = fx::readTextFile(fifo);  // would block forever without O_NONBLOCK
    ASSERT_FALSE(read.ok());
    EXPECT_NE(read.error().find("FIFO"), std::string::npos) << read.error();
}

TEST(FileIo, ASocketIsRefused) {
    TempFolder dir("fx_file_io_socket");
    fs::path socketPath = dir.path / "s.json";
    int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
    ASSERT_GE(fd, 0);
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    std::snprintf(address.sun_path, sizeof address.sun_path, "%s", socketPath.c_str());
    ASSERT_EQ(::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
    auto status = fx::writeFileAtomically(socketPath, std::string_view("x"));
    ::close(fd);
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.error().find("is a socket"), std::string::npos) << status.error();
    EXPECT_TRUE(fs::is_socket(socketPath));
}

TEST(FileIo, ALinkedSubfolderIsNotFollowedOutOfTheChosenFolder) {
    // --capture DIR where DIR/step-1 is a link to another folder: nothing is written there.
    TempFolder dir("fx_file_io_subfolder");
    TempFolder elsewhere("fx_file_io_subfolder_elsewhere");
    fs::create_symlink(elsewhere.path, dir.path / "step-1");
    auto status = fx::writeFileInFolder(dir.path, "step-1/final.png", std::string_view("png"));
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.error().find("step-1: is a symbolic link"), std::string::npos) << status.error();
    EXPECT_TRUE(fs::is_empty(elsewhere.path));
    EXPECT_NE(fx::makeFolderIn(dir.path, "step-1").error(), "");
    // A real subfolder is made, and used.
    ASSERT_TRUE(fx::writeFileInFolder(dir.path, "step-2/final.png", std::string_view("png")).ok());
    EXPECT_EQ(*fx::readTextFile(dir.path / "step-2" / "final.png"), "png");
    ASSERT_TRUE(fx::makeFolderIn(dir.path, "step-3").ok());
    EXPECT_TRUE(fs::is_directory(dir.path / "step-3"));
}

TEST(FileIo, ANameThatClimbsOutOfTheFolderIsRefused) {
    TempFolder dir("fx_file_io_climb");
    for (const char* name : {"../escaped.txt", "a/../../escaped.txt", "/tmp/absolute.txt", ""}) {
        auto status = fx::writeFileInFolder(dir.path / "inner", name, std::string_view("x"));
        EXPECT_FALSE(status.ok()) << name;
    }
    EXPECT_FALSE(fs::exists(dir.path / "escaped.txt"));
    EXPECT_FALSE(fs::exists("/tmp/absolute.txt"));
}

TEST(FileIo, TheChosenFolderMayBeALinkTheUserNamed) {
    // The folder itself is the user's choice: a link they name is followed, once, to that folder.
    TempFolder dir("fx_file_io_chosen");
    fs::create_directories(dir.path / "real");
    fs::create_symlink(dir.path / "real", dir.path / "chosen");
    ASSERT_TRUE(fx::writeFileAtomically(dir.path / "chosen" / "a.txt", std::string_view("a")).ok());
    EXPECT_EQ(*fx::readTextFile(dir.path / "real" / "a.txt"), "a");
}

TEST(FileIo, AStaleTemporaryLinkIsNotFollowed) {
    // Something planted at the temporary name is removed, never written through.
    TempFolder dir("fx_file_io_temp");
    TempFolder elsewhere("fx_file_io_temp_elsewhere");
    fs::path victim = elsewhere.path / "victim";
    ASSERT_TRUE(fx::writeFileAtomically(victim, std::string_view("keep")).ok());
    fs::create_symlink(victim, dir.path / ("out.txt.tmp" + std::to_string(::getpid())));
    ASSERT_TRUE(fx::writeFileAtomically(dir.path / "out.txt", std::string_view("new")).ok());
    EXPECT_EQ(*fx::readTextFile(victim), "keep");
    EXPECT_EQ(*fx::readTextFile(dir.path / "out.txt"), "new");
}

TEST(FileIo, ADashWritesStandardOutput) {
    EXPECT_TRUE(fx::namesStandardOutput("-"));
    EXPECT_FALSE(fx::namesStandardOutput("./-"));
    EXPECT_FALSE(fx::namesStandardOutput("/dev/stdout"));
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
