#include "base/output_folder.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <optional>

#include <sys/stat.h>
#include <unistd.h>

#include "base/file_io.hpp"
#include "base/log.hpp"

namespace fx {
namespace {

namespace fs = std::filesystem;

std::string describeNonFolder(mode_t mode) {
    if (S_ISLNK(mode)) return "a symbolic link (no folder is written through a link)";
    if (S_ISREG(mode)) return "a file, not a folder";
    if (S_ISFIFO(mode)) return "a FIFO (named pipe), not a folder";
    if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device, not a folder";
    if (S_ISSOCK(mode)) return "a socket, not a folder";
    return "not a folder";
}

// Why a full folder may not be replaced even with --force, or nothing: it must hold the marker (a
// regular file, not a link to one) that begin() writes into every folder it makes.
std::optional<std::string> notWrittenByFxlab(const fs::path& target) {
    struct stat st {};
    if (::lstat((target / kStagedFolderMarker).c_str(), &st) == 0 && S_ISREG(st.st_mode)) return std::nullopt;
    return cat(target.string(), ": a folder with files in it that fxlab did not write (it has no ",
               kStagedFolderMarker,
               "); --force replaces only a folder an earlier handout wrote, so this one "
               "is kept as it is: give the handout a new folder, or empty this one yourself");
}

enum class TargetState { Missing, Empty, Full };

// What is at the target now, or why it may not be replaced.
Result<TargetState> inspectTarget(const fs::path& target, bool replace) {
    struct stat st {};
    if (::lstat(target.c_str(), &st) != 0) {
        if (errno == ENOENT) return TargetState::Missing;
        if (errno == ENOTDIR)
            return Error{cat(target.string(), ": a part of this path is a file, not a folder")};
        return Error{cat(target.string(), ": ", std::strerror(errno))};
    }
    if (!S_ISDIR(st.st_mode)) return Error{cat(target.string(), ": ", describeNonFolder(st.st_mode))};
    std::error_code ec;
    fs::directory_iterator it(target, ec);
    if (ec) return Error{cat(target.string(), ": ", ec.message())};
    if (it == fs::directory_iterator()) return TargetState::Empty;
    if (!replace) return Error{cat(target.string(), ": a folder with files in it; --force replaces it")};
    if (auto notOurs = notWrittenByFxlab(target)) return Error{*notOurs};
    return TargetState::Full;
}

// A name beside the target that nothing else uses: ".<name>.<what>-<pid>[-n]".
fs::path siblingName(const fs::path& target, const char* what) {
    const fs::path parent = target.parent_path();
    const std::string base = cat(".", target.filename().string(), ".", what, "-", ::getpid());
    fs::path candidate = parent / base;
    std::error_code ec;
    for (int n = 2; fs::symlink_status(candidate, ec).type() != fs::file_type::not_found; ++n)
        candidate = parent / cat(base, "-", n);
    return candidate;
}

}  // namespace

StagedFolder::StagedFolder(fs::path target, fs::path staging, bool replace)
    : target_(std::move(target)), staging_(std::move(staging)), replace_(replace) {}

Result<std::unique_ptr<StagedFolder>> StagedFolder::begin(const fs::path& requested, bool replace) {
    if (requested.empty()) return Error{"output folder: no path given"};
    std::error_code ec;
    fs::path target = fs::absolute(requested, ec).lexically_normal();
    if (!target.has_filename()) target = target.parent_path();  // "out/h/" is "out/h"
    // ".", "..", "/": the folder this runs in, or one around it, is never replaced.
    const fs::path here = fs::current_path(ec);
    const auto inside = here.lexically_relative(target);
    if (ec || target == target.root_path() || (!inside.empty() && *inside.begin() != ".."))
        return Error{
            cat(requested.string(), ": holds the current folder; give the handout a folder of its own")};
    if (auto state = inspectTarget(target, replace); !state) return Error{state.error()};
    fs::create_directories(target.parent_path(), ec);
    if (ec) return Error{cat(target.parent_path().string(), ": cannot make the folder: ", ec.message())};
    fs::path staging = siblingName(target, "partial");
    if (::mkdir(staging.c_str(), 0755) != 0)
        return Error{cat(target.parent_path().string(), ": cannot write here: ", std::strerror(errno))};
    auto folder = std::unique_ptr<StagedFolder>(new StagedFolder(target, staging, replace));
    if (auto s = writeFileInFolder(
            staging, kStagedFolderMarker,
            std::string_view("fxlab wrote this folder; fxlab-handout --force may replace it\n"));
        !s)
        return Error{s.error()};
    return folder;
}

StagedFolder::~StagedFolder() {
    if (committed_) return;
    std::error_code ec;
    fs::remove_all(staging_, ec);
    if (ec) log::warning("could not remove the unfinished folder ", staging_.string(), ": ", ec.message());
}

Status StagedFolder::commit() {
    auto state = inspectTarget(target_, replace_);
    if (!state) return Error{state.error()};
    if (*state != TargetState::Full) {
        // rename(2) puts a folder in place of nothing or of an empty folder, in one step.
        if (::rename(staging_.c_str(), target_.c_str()) != 0)
            return Error{
                cat(target_.string(), ": cannot put the new folder in place: ", std::strerror(errno))};
        committed_ = true;
        return Status::success();
    }
    const fs::path old = siblingName(target_, "replaced");
    if (::rename(target_.c_str(), old.c_str()) != 0)
        return Error{cat(target_.string(), ": cannot move the old folder aside: ", std::strerror(errno))};
    if (::rename(staging_.c_str(), target_.c_str()) != 0) {
        const int saved = errno;
        (void)::rename(old.c_str(), target_.c_str());
        return Error{cat(target_.string(), ": cannot put the new folder in place: ", std::strerror(saved))};
    }
    committed_ = true;
    std::error_code ec;
    fs::remove_all(old, ec);
    if (ec)
        log::warning("the new ", target_.string(), " is in place; the old one is left at ", old.string(),
                     ": ", ec.message());
    return Status::success();
}

}  // namespace fx
