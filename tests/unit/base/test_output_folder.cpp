// A folder written whole or not at all (base/output_folder.hpp): the handout's output.
#include <gtest/gtest.h>

#include <filesystem>

#include <sys/stat.h>
#include <unistd.h>

#include "base/file_io.hpp"
#include "base/output_folder.hpp"

namespace fs = std::filesystem;

namespace {

class OutputFolder : public ::testing::Test {
protected:
    void SetUp() override {
        root_ = fs::temp_directory_path() / ("fx_output_folder_" + std::to_string(::getpid()));
        fs::remove_all(root_);
        fs::create_directories(root_);
    }
    void TearDown() override {
        fs::permissions(root_, fs::perms::owner_all, fs::perm_options::add);
        fs::remove_all(root_);
    }
    // Everything in root_, sorted: what a run left behind.
    std::vector<std::string> entries() const {
        std::vector<std::string> names;
        for (auto& e : fs::directory_iterator(root_)) names.push_back(e.path().filename().string());
        std::sort(names.begin(), names.end());
        return names;
    }
    fs::path root_;
};

TEST_F(OutputFolder, AppearsOnlyWhenCommitted) {
    auto staged = fx::StagedFolder::begin(root_ / "nested" / "out", false);
    ASSERT_TRUE(staged.ok()) << staged.error();
    ASSERT_TRUE(fx::writeFileAtomically((*staged)->path() / "index.html", std::string_view("x")).ok());
    EXPECT_FALSE(fs::exists(root_ / "nested" / "out"));  // nothing at the target while it is written
    EXPECT_EQ((*staged)->path().parent_path(), root_ / "nested");
    ASSERT_TRUE((*staged)->commit().ok());
    EXPECT_TRUE(fs::is_regular_file(root_ / "nested" / "out" / "index.html"));
    staged->reset();
    EXPECT_EQ(entries(), std::vector<std::string>{"nested"});
    EXPECT_EQ(fs::directory_iterator(root_ / "nested")->path().filename(), "out");  // no sibling left
}

TEST_F(OutputFolder, AFailedRunLeavesNothing) {
    {
        auto staged = fx::StagedFolder::begin(root_ / "out", false);
        ASSERT_TRUE(staged.ok());
        ASSERT_TRUE(fx::writeFileAtomically((*staged)->path() / "a" / "b.png", std::string_view("x")).ok());
    }  // never committed
    EXPECT_TRUE(entries().empty());
}

TEST_F(OutputFolder, AFolderWithFilesIsRefusedUnlessReplaced) {
    {  // an earlier handout: a folder StagedFolder wrote, with its marker
        auto earlier = fx::StagedFolder::begin(root_ / "out", false);
        ASSERT_TRUE(earlier.ok()) << earlier.error();
        ASSERT_TRUE(fx::writeFileAtomically((*earlier)->path() / "old.html", std::string_view("old")).ok());
        ASSERT_TRUE((*earlier)->commit().ok());
    }
    EXPECT_TRUE(fs::is_regular_file(root_ / "out" / fx::kStagedFolderMarker));
    auto refused = fx::StagedFolder::begin(root_ / "out", false);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.error(), (root_ / "out").string() + ": a folder with files in it; --force replaces it");
    EXPECT_EQ(entries(), std::vector<std::string>{"out"});

    auto staged = fx::StagedFolder::begin(root_ / "out", true);
    ASSERT_TRUE(staged.ok()) << staged.error();
    ASSERT_TRUE(fx::writeFileAtomically((*staged)->path() / "new.html", std::string_view("new")).ok());
    EXPECT_TRUE(fs::exists(root_ / "out" / "old.html"));  // the old one stays until the new one is whole
    ASSERT_TRUE((*staged)->commit().ok());
    EXPECT_FALSE(fs::exists(root_ / "out" / "old.html"));
    EXPECT_TRUE(fs::exists(root_ / "out" / "new.html"));
    EXPECT_TRUE(fs::is_regular_file(root_ / "out" / fx::kStagedFolderMarker));  // replaceable again
    EXPECT_EQ(entries(), std::vector<std::string>{"out"});
}

// Issue 40, defect 1: --force on a folder of the user's (a home folder) left only the handout.
TEST_F(OutputFolder, ForceNeverReplacesAFolderFxlabDidNotWrite) {
    ASSERT_TRUE(fx::writeFileAtomically(root_ / "home" / ".ssh" / "id_rsa", std::string_view("key")).ok());
    ASSERT_TRUE(
        fx::writeFileAtomically(root_ / "home" / "Documents" / "thesis.tex", std::string_view("t")).ok());
    auto refused = fx::StagedFolder::begin(root_ / "home", true);
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().find((root_ / "home").string() +
                                   ": a folder with files in it that fxlab did not write"),
              std::string::npos)
        << refused.error();
    EXPECT_NE(refused.error().find("--force replaces only a folder an earlier handout wrote"),
              std::string::npos);
    EXPECT_EQ(entries(), std::vector<std::string>{"home"});  // no staging folder left beside it
    EXPECT_EQ(*fx::readTextFile(root_ / "home" / ".ssh" / "id_rsa"), "key");

    // A marker that is a link (to a file elsewhere) or a folder does not count.
    ASSERT_TRUE(fx::writeFileAtomically(root_ / "elsewhere", std::string_view("x")).ok());
    fs::create_symlink(root_ / "elsewhere", root_ / "home" / fx::kStagedFolderMarker);
    EXPECT_FALSE(fx::StagedFolder::begin(root_ / "home", true).ok());
    fs::remove(root_ / "home" / fx::kStagedFolderMarker);
    fs::create_directory(root_ / "home" / fx::kStagedFolderMarker);
    EXPECT_FALSE(fx::StagedFolder::begin(root_ / "home", true).ok());

    // A folder that was the handout's when the run began but lost its marker is not replaced at the commit.
    fs::remove(root_ / "home" / fx::kStagedFolderMarker);
    ASSERT_TRUE(fx::writeFileAtomically(root_ / "home" / fx::kStagedFolderMarker, std::string_view("")).ok());
    auto staged = fx::StagedFolder::begin(root_ / "home", true);
    ASSERT_TRUE(staged.ok()) << staged.error();
    fs::remove(root_ / "home" / fx::kStagedFolderMarker);
    EXPECT_FALSE((*staged)->commit().ok());
    EXPECT_EQ(*fx::readTextFile(root_ / "home" / "Documents" / "thesis.tex"), "t");
}

TEST_F(OutputFolder, AnEmptyFolderIsTakenOver) {
    fs::create_directories(root_ / "out");
    auto staged = fx::StagedFolder::begin(root_ / "out/", false);  // a trailing slash names the same folder
    ASSERT_TRUE(staged.ok()) << staged.error();
    ASSERT_TRUE(fx::writeFileAtomically((*staged)->path() / "index.html", std::string_view("x")).ok());
    ASSERT_TRUE((*staged)->commit().ok());
    EXPECT_TRUE(fs::exists(root_ / "out" / "index.html"));
}

TEST_F(OutputFolder, NothingButAFolderIsEverReplaced) {
    ASSERT_TRUE(fx::writeFileAtomically(root_ / "file", std::string_view("keep")).ok());
    fs::create_directories(root_ / "real");
    fs::create_directory_symlink(root_ / "real", root_ / "link");
    ASSERT_EQ(::mkfifo((root_ / "fifo").c_str(), 0600), 0);
    for (const char* name : {"file", "link", "fifo"}) {
        for (bool replace : {false, true}) {
            auto staged = fx::StagedFolder::begin(root_ / name, replace);
            ASSERT_FALSE(staged.ok()) << name;
            EXPECT_NE(staged.error().find((root_ / name).string() + ": "), std::string::npos)
                << staged.error();
        }
    }
    EXPECT_NE(fx::StagedFolder::begin(root_ / "link", true).error().find("symbolic link"), std::string::npos);
    EXPECT_NE(fx::StagedFolder::begin(root_ / "fifo", true).error().find("FIFO"), std::string::npos);
    EXPECT_NE(fx::StagedFolder::begin("/dev/null", true).error().find("a device, not a folder"),
              std::string::npos);
    EXPECT_EQ(entries(), (std::vector<std::string>{"fifo", "file", "link", "real"}));
    EXPECT_EQ(*fx::readTextFile(root_ / "file"), "keep");
}

TEST_F(OutputFolder, ATargetThatChangesBeforeTheCommitIsNotReplaced) {
    auto staged = fx::StagedFolder::begin(root_ / "out", false);
    ASSERT_TRUE(staged.ok());
    ASSERT_TRUE(fx::writeFileAtomically(root_ / "out" / "theirs.txt", std::string_view("x")).ok());
    auto committed = (*staged)->commit();
    ASSERT_FALSE(committed.ok());
    EXPECT_NE(committed.error().find("a folder with files in it"), std::string::npos);
    EXPECT_TRUE(fs::exists(root_ / "out" / "theirs.txt"));
}

TEST_F(OutputFolder, AnUnwritableParentIsAClearError) {
    if (::geteuid() == 0) GTEST_SKIP() << "root writes anywhere";
    fs::create_directories(root_ / "locked");
    fs::permissions(root_ / "locked", fs::perms::owner_read | fs::perms::owner_exec);
    auto staged = fx::StagedFolder::begin(root_ / "locked" / "out", false);
    ASSERT_FALSE(staged.ok());
    EXPECT_NE(staged.error().find("cannot write here"), std::string::npos) << staged.error();
    fs::permissions(root_ / "locked", fs::perms::owner_all);
}

TEST_F(OutputFolder, AParentThatIsAFileIsAClearError) {
    ASSERT_TRUE(fx::writeFileAtomically(root_ / "file", std::string_view("keep")).ok());
    auto staged = fx::StagedFolder::begin(root_ / "file" / "out", false);
    ASSERT_FALSE(staged.ok());
    EXPECT_EQ(staged.error(),
              (root_ / "file" / "out").string() + ": a part of this path is a file, not a folder");
    EXPECT_EQ(entries(), std::vector<std::string>{"file"});
}

TEST_F(OutputFolder, TheFolderItRunsInIsNeverReplaced) {
    const fs::path before = fs::current_path();
    fs::create_directories(root_ / "work" / "sub");
    fs::current_path(root_ / "work" / "sub");
    for (const char* path : {".", "..", "./", "../sub", "/"}) {
        auto staged = fx::StagedFolder::begin(path, true);
        ASSERT_FALSE(staged.ok()) << path;
        EXPECT_NE(staged.error().find("holds the current folder"), std::string::npos) << staged.error();
    }
    EXPECT_TRUE(fx::StagedFolder::begin("../other", true).ok());  // a sibling is fine
    fs::current_path(before);
    EXPECT_FALSE(fx::StagedFolder::begin("", true).ok());
}

}  // namespace
