// The Windows side of the platform code, run under Wine (label windows): the write rule with Windows'
// names and links, reads that refuse devices, a folder staged over an empty one, the watchdog's child
// started as this program again, arguments and paths with Japanese characters through CreateProcessW,
// PATH with ';' and PATHEXT, the user's folders, and the process's memory. Its own main(): the
// watchdog's child is this program (app/child_watchdog.hpp), which gtest_main could not serve.
#include <gtest/gtest.h>

#include <windows.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <thread>
#include <vector>

#include "app/child_watchdog.hpp"
#include "app/handout_io.hpp"
#include "app/lesson_switch.hpp"
#include "app/process_start.hpp"
#include "base/file_io.hpp"
#include "base/output_folder.hpp"
#include "base/process_memory.hpp"
#include "base/user_folders.hpp"
#include "base/utf8_path.hpp"

namespace fs = std::filesystem;
using namespace fx;

namespace {

// A fresh folder with Japanese names on the way (as C:\Users\山田\… on a Japanese Windows).
class JapaneseFolder : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        root_ = fs::temp_directory_path() / fs::path(u8"fxlab 試験") /
                (std::string(info->name()) + "-" + std::to_string(GetCurrentProcessId()));
        fs::remove_all(root_);
        dir_ = root_ / fs::path(u8"山田") / fs::path(u8"日本語のフォルダー");
        fs::create_directories(dir_);
    }
    void TearDown() override {
        std::error_code ec;
        fs::remove_all(root_.parent_path(), ec);
    }
    static std::string read(const fs::path& p) {
        auto text = readTextFile(p);
        return text ? *text : "(unreadable: " + text.error() + ")";
    }
    fs::path root_, dir_;
};

std::string utf8(const fs::path& p) {
    const std::u8string s = p.u8string();
    return std::string(s.begin(), s.end());
}

}  // namespace

TEST_F(JapaneseFolder, WritesAndReplacesAFileWhoseNameIsJapanese) {
    const fs::path name = fs::path(u8"結果") / fs::path(u8"画像.txt");
    ASSERT_TRUE(writeFileInFolder(dir_, name, std::string_view("first")).ok());
    EXPECT_TRUE(fs::is_regular_file(dir_ / name)) << "the wide name on disk is the UTF-8 name fxlab holds";
    EXPECT_EQ(read(dir_ / name), "first");
    // Windows will not move a file over one another program holds open, even with FILE_SHARE_DELETE
    // (an editor, a viewer): the write fails with a message naming the file, the old file stays
    // whole, and nothing is left beside it; once it is closed, the write goes through.
    HANDLE reader = CreateFileW((dir_ / name).c_str(), GENERIC_READ,
                                FILE_SHARE_READ | FILE_SHARE_WRITE | FILE_SHARE_DELETE, nullptr,
                                OPEN_EXISTING, 0, nullptr);
    ASSERT_NE(reader, INVALID_HANDLE_VALUE);
    Status whileOpen = writeFileInFolder(dir_, name, std::string_view("second"));
    CloseHandle(reader);
    if (!whileOpen.ok()) {
        EXPECT_NE(whileOpen.error().find(reinterpret_cast<const char*>(u8"画像.txt")), std::string::npos)
            << whileOpen.error();
        EXPECT_EQ(read(dir_ / name), "first");
    }
    Status second = writeFileInFolder(dir_, name, std::string_view("second"));
    ASSERT_TRUE(second.ok()) << second.error();
    EXPECT_EQ(read(dir_ / name), "second");
    // Nothing left beside it: the temporary file was moved into place.
    int files = 0;
    for (const auto& e : fs::directory_iterator(dir_ / fs::path(u8"結果"))) {
        (void)e;
        ++files;
    }
    EXPECT_EQ(files, 1);
    // The same path, given as the UTF-8 text fxlab passes around (a command line, a JSON file):
    // pathFromUtf8 reads it as UTF-8, where MinGW's path(std::string) would not.
    EXPECT_TRUE(
        writeFileAtomically(pathFromUtf8(utf8(dir_ / fs::path(u8"二つ目.json"))), std::string_view("{}"))
            .ok());
    EXPECT_TRUE(fs::exists(dir_ / fs::path(u8"二つ目.json")));
}

TEST_F(JapaneseFolder, RefusesTheNamesWindowsKeepsForDevices) {
    for (const char* name :
         {"CON", "nul", "NUL.txt", "com1", "COM9.png", "LPT1", "aux.json", "PRN", "conout$"}) {
        Status s = writeFileInFolder(dir_, name, std::string_view("x"));
        ASSERT_FALSE(s.ok()) << name;
        EXPECT_NE(s.error().find("Windows device"), std::string::npos) << s.error();
    }
    Status inside = writeFileInFolder(dir_, "con/report.json", std::string_view("x"));
    EXPECT_FALSE(inside.ok()) << "a device name as a folder on the way";
    // Names that only look alike are fine.
    for (const char* name : {"CONSOLE.txt", "com10.txt", "nul-result.png", "COM.txt"})
        EXPECT_TRUE(writeFileInFolder(dir_, name, std::string_view("x")).ok()) << name;
}

TEST_F(JapaneseFolder, RefusesNamesEndingInADotOrASpace) {
    for (const char* name : {"report.", "report ", "step-1./final.png"}) {
        Status s = writeFileInFolder(dir_, name, std::string_view("x"));
        ASSERT_FALSE(s.ok()) << name;
        EXPECT_NE(s.error().find("dot or a space"), std::string::npos) << s.error();
    }
    EXPECT_FALSE(fs::exists(dir_ / "report"));
}

TEST_F(JapaneseFolder, RefusesAFolderAtTheTargetAndLeavesItAlone) {
    fs::create_directories(dir_ / "out.png" / "keep");
    Status s = writeFileInFolder(dir_, "out.png", std::string_view("x"));
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().find("is a folder"), std::string::npos) << s.error();
    EXPECT_TRUE(fs::is_directory(dir_ / "out.png" / "keep"));
}

TEST_F(JapaneseFolder, NeverWritesThroughALink) {
    const fs::path victim = root_ / "victim.txt";
    ASSERT_TRUE(writeFileAtomically(victim, std::string_view("the user's")).ok());
    if (!CreateSymbolicLinkW((dir_ / "link.txt").c_str(), victim.c_str(), 0) &&
        !CreateSymbolicLinkW((dir_ / "link.txt").c_str(), victim.c_str(), 0x2 /* unprivileged */))
        GTEST_SKIP()
            << "no symbolic links here (Windows makes them only in Developer Mode or as administrator)";
    const DWORD attributes = GetFileAttributesW((dir_ / "link.txt").c_str());
    const bool seenAsLink =
        attributes != INVALID_FILE_ATTRIBUTES && (attributes & FILE_ATTRIBUTE_REPARSE_POINT);
    Status s = writeFileInFolder(dir_, "link.txt", std::string_view("through the link"));
    EXPECT_EQ(read(victim), "the user's") << "never written through the link";
    if (!seenAsLink)
        GTEST_SKIP()
            << "this system does not report the link as a reparse point (Wine): the link's target was "
               "left alone, but whether the link itself is refused is untested here";
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().find("link"), std::string::npos) << s.error();
}

TEST_F(JapaneseFolder, ClimbingOutOrAbsoluteNamesAreRefused) {
    EXPECT_FALSE(writeFileInFolder(dir_, "../escaped.txt", std::string_view("x")).ok());
    EXPECT_FALSE(writeFileInFolder(dir_, "C:/escaped.txt", std::string_view("x")).ok());
    EXPECT_FALSE(fs::exists(dir_.parent_path() / "escaped.txt"));
}

TEST_F(JapaneseFolder, ReadsOnlyRegularFiles) {
    auto device = readFile("NUL", file_limits::text);
    ASSERT_FALSE(device.ok());
    EXPECT_NE(device.error().find("not a file"), std::string::npos) << device.error();
    auto folder = readFile(dir_, file_limits::text);
    ASSERT_FALSE(folder.ok());
    EXPECT_NE(folder.error().find("a folder"), std::string::npos) << folder.error();
    ASSERT_TRUE(writeFileInFolder(dir_, "big.txt", std::string(2000, 'x')).ok());
    auto big = readFile(dir_ / "big.txt", FileLimit{"test file", 1000});
    ASSERT_FALSE(big.ok());
    EXPECT_NE(big.error().find("over the limit"), std::string::npos) << big.error();
    auto missing = readFile(dir_ / fs::path(u8"ない.txt"), file_limits::text);
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().find("cannot open"), std::string::npos) << missing.error();
    EXPECT_NE(missing.error().find(reinterpret_cast<const char*>(u8"ない.txt")), std::string::npos)
        << "the message names the file in UTF-8: " << missing.error();
}

TEST_F(JapaneseFolder, StagesAFolderOverAnEmptyOneAndOverAFullOne) {
    const fs::path target = dir_ / fs::path(u8"配布資料");
    fs::create_directories(target);  // Windows will not move a folder over an empty one
    {
        auto staged = StagedFolder::begin(target, false);
        ASSERT_TRUE(staged.ok()) << staged.error();
        ASSERT_TRUE(writeFileAtomically((*staged)->path() / "index.html", std::string_view("one")).ok());
        Status done = (*staged)->commit();
        ASSERT_TRUE(done.ok()) << done.error();
    }
    EXPECT_EQ(read(target / "index.html"), "one");
    auto refused = StagedFolder::begin(target, false);
    EXPECT_FALSE(refused.ok()) << "a folder with files in it is replaced only with --force";
    {
        auto staged = StagedFolder::begin(target, true);
        ASSERT_TRUE(staged.ok()) << staged.error();
        ASSERT_TRUE(writeFileAtomically((*staged)->path() / "index.html", std::string_view("two")).ok());
        Status done = (*staged)->commit();
        ASSERT_TRUE(done.ok()) << done.error();
    }
    EXPECT_EQ(read(target / "index.html"), "two");
    int entries = 0;
    for (const auto& e : fs::directory_iterator(dir_)) {
        (void)e;
        ++entries;
    }
    EXPECT_EQ(entries, 1) << "neither the staged nor the replaced folder is left beside it";
}

TEST(Watchdog, EndsAChildThatDoesNotFinishAndHearsOneThatDoes) {
    const auto start = std::chrono::steady_clock::now();
    ChildOutcome hung = runInChildWithin("test-hang", {}, 2.0);
    EXPECT_EQ(hung.kind, ChildOutcome::Kind::timedOut);
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(15));

    // Arguments with spaces, quotes, backslashes and Japanese arrive as they were sent.
    const std::vector<std::string> arguments{
        reinterpret_cast<const char*>(u8"C:\\Users\\山田\\fxlab exercises\\"), "say \"hi\"", "",
        "a\\\\b\\\"c"};
    ChildOutcome done = runInChildWithin("test-echo", arguments, 30.0);
    ASSERT_EQ(done.kind, ChildOutcome::Kind::finished) << done.reason;
    std::string expected;
    for (const std::string& a : arguments) expected += "[" + a + "]";
    EXPECT_EQ(done.answer, expected);

    ChildOutcome crashed = runInChildWithin("test-abort", {}, 30.0);
    EXPECT_EQ(crashed.kind, ChildOutcome::Kind::crashed);
    EXPECT_FALSE(crashed.reason.empty());

    ChildOutcome unknown = runInChildWithin("no-such-work", {}, 10.0);
    EXPECT_EQ(unknown.kind, ChildOutcome::Kind::notStarted);
}

TEST(Processes, RunAndWaitGivesTheExitCodeAndTheOutput) {
    const fs::path log = fs::temp_directory_path() / fs::path(u8"fxlab 出力.log");
    auto code = runAndWait(runningExecutable(), {"--fx-child", "test-exit", "7"}, log);
    ASSERT_TRUE(code.ok()) << code.error();
    EXPECT_EQ(*code, 7);
    auto text = readTextFile(log);
    ASSERT_TRUE(text.ok()) << text.error();
    EXPECT_NE(text->find("exiting with 7"), std::string::npos) << *text;
    fs::remove(log);
    EXPECT_EQ(programName(runningExecutable()), "fx_windows_platform_test");
}

TEST(Processes, FindsProgramsOnPathWithPathext) {
    const fs::path cmd = handout::findProgram("cmd");
    ASSERT_FALSE(cmd.empty()) << "cmd.exe is on every Windows PATH";
    EXPECT_EQ(cmd.filename().string().size(), 7u) << cmd.string();
    EXPECT_TRUE(handout::findProgram("no-such-program-fxlab").empty());
}

TEST(UserFolders, AreTheOnesWindowsKeeps) {
    auto config = userConfigFolder();
    auto home = userHomeFolder();
    ASSERT_TRUE(config.has_value());
    ASSERT_TRUE(home.has_value());
    EXPECT_TRUE(fs::is_directory(*config)) << config->string();
    EXPECT_TRUE(fs::is_directory(*home)) << home->string();
    if (const char* appdata = std::getenv("APPDATA")) {
        EXPECT_EQ(pathFromUtf8(appdata), *config);
    }
}

TEST(ProcessMemory, CountsTheHeapAndTheWorkingSet) {
    const ProcessMemory before = processMemory();
    EXPECT_GT(before.residentBytes, 1u << 20);
    // 200,000 blocks of 256 bytes (50 MB), each touched: what a leak that grows looks like.
    std::vector<std::unique_ptr<char[]>> blocks;
    for (int i = 0; i < 200000; ++i) {
        blocks.push_back(std::make_unique<char[]>(256));
        blocks.back()[0] = char(i);
    }
    const ProcessMemory after = processMemory();
    EXPECT_GE(after.heapBytes, before.heapBytes + (40u << 20));
    EXPECT_GT(after.residentBytes, before.residentBytes + (32u << 20));
}

int main(int argc, char** argv) {
    registerChildWork("test-hang", [](const std::vector<std::string>&) {
        // Far longer than the watchdog's time, but finite: a broken watchdog fails, not hangs.
        for (int second = 0; second < 30; ++second) std::this_thread::sleep_for(std::chrono::seconds(1));
        return std::string("finished too late");
    });
    registerChildWork("test-echo", [](const std::vector<std::string>& arguments) {
        std::string answer;
        for (const std::string& a : arguments) answer += "[" + a + "]";
        return answer;
    });
    registerChildWork("test-abort", [](const std::vector<std::string>&) {
        std::abort();
        return std::string();
    });
    registerChildWork("test-exit", [](const std::vector<std::string>& arguments) {
        std::fprintf(stderr, "exiting with %s\n", arguments.at(0).c_str());
        std::fflush(stderr);
        std::exit(std::atoi(arguments.at(0).c_str()));
        return std::string();
    });
    const std::vector<std::string> args = programArguments(argc, argv);
    if (auto code = runChildWorkIfAsked(args)) return *code;
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
