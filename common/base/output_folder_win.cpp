// StagedFolder on Windows (base/output_folder.hpp; the POSIX twin is output_folder_posix.cpp, which
// this follows step for step). Two differences: a link is a reparse point, and Windows will not move
// a folder over an empty one, so the empty one is removed first (RemoveDirectoryW removes only an
// empty folder, so nothing of the user's can go with it).
#include "base/output_folder.hpp"

#include <windows.h>

#include "base/log.hpp"
#include "base/windows_text.hpp"

namespace fx {
namespace {

namespace fs = std::filesystem;

enum class TargetState { Missing, Empty, Full };

// What is at the target now, or why it may not be replaced.
Result<TargetState> inspectTarget(const fs::path& target, bool replace) {
    const DWORD attributes = GetFileAttributesW(target.c_str());
    if (attributes == INVALID_FILE_ATTRIBUTES) {
        const DWORD error = GetLastError();
        if (error == ERROR_FILE_NOT_FOUND) return TargetState::Missing;
        if (error == ERROR_PATH_NOT_FOUND) {
            // A missing folder on the way is fine (it is made); a file on the way is not.
            for (fs::path up = target.parent_path(); !up.empty() && up != up.root_path();
                 up = up.parent_path()) {
                const DWORD a = GetFileAttributesW(up.c_str());
                if (a == INVALID_FILE_ATTRIBUTES) continue;
                if (!(a & FILE_ATTRIBUTE_DIRECTORY))
                    return Error{cat(target.string(), ": a part of this path is a file, not a folder")};
                break;
            }
            return TargetState::Missing;
        }
        return Error{cat(target.string(), ": ", windows::errorText(error))};
    }
    if (attributes & FILE_ATTRIBUTE_REPARSE_POINT)
        return Error{cat(target.string(), ": a link (reparse point; no folder is written through a link)")};
    if (!(attributes & FILE_ATTRIBUTE_DIRECTORY))
        return Error{cat(target.string(), ": a file, not a folder")};
    std::error_code ec;
    fs::directory_iterator it(target, ec);
    if (ec) return Error{cat(target.string(), ": ", ec.message())};
    if (it == fs::directory_iterator()) return TargetState::Empty;
    if (!replace) return Error{cat(target.string(), ": a folder with files in it; --force replaces it")};
    return TargetState::Full;
}

// A name beside the target that nothing else uses: ".<name>.<what>-<pid>[-n]".
fs::path siblingName(const fs::path& target, const char* what) {
    const fs::path parent = target.parent_path();
    const std::string base = cat(".", target.filename().string(), ".", what, "-", GetCurrentProcessId());
    fs::path candidate = parent / base;
    std::error_code ec;
    for (int n = 2; fs::symlink_status(candidate, ec).type() != fs::file_type::not_found; ++n)
        candidate = parent / cat(base, "-", n);
    return candidate;
}

bool moveFolder(const fs::path& from, const fs::path& to) {
    return MoveFileExW(from.c_str(), to.c_str(), 0) != 0;
}

}  // namespace

StagedFolder::StagedFolder(fs::path target, fs::path staging, bool replace)
    : target_(std::move(target)), staging_(std::move(staging)), replace_(replace) {}

Result<std::unique_ptr<StagedFolder>> StagedFolder::begin(const fs::path& requested, bool replace) {
    if (requested.empty()) return Error{"output folder: no path given"};
    std::error_code ec;
    fs::path target = fs::absolute(requested, ec).lexically_normal();
    if (!target.has_filename()) target = target.parent_path();  // "out\h\" is "out\h"
    // ".", "..", "C:\": the folder this runs in, or one around it, is never replaced.
    const fs::path here = fs::current_path(ec);
    const auto inside = here.lexically_relative(target);
    if (ec || target == target.root_path() || (!inside.empty() && *inside.begin() != ".."))
        return Error{
            cat(requested.string(), ": holds the current folder; give the handout a folder of its own")};
    if (auto state = inspectTarget(target, replace); !state) return Error{state.error()};
    fs::create_directories(target.parent_path(), ec);
    if (ec) return Error{cat(target.parent_path().string(), ": cannot make the folder: ", ec.message())};
    fs::path staging = siblingName(target, "partial");
    if (!CreateDirectoryW(staging.c_str(), nullptr))
        return Error{cat(target.parent_path().string(), ": cannot write here: ", windows::lastErrorText())};
    return std::unique_ptr<StagedFolder>(new StagedFolder(target, staging, replace));
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
    if (*state == TargetState::Empty && !RemoveDirectoryW(target_.c_str()))
        return Error{
            cat(target_.string(), ": cannot put the new folder in place: ", windows::lastErrorText())};
    if (*state != TargetState::Full) {
        if (!moveFolder(staging_, target_))
            return Error{
                cat(target_.string(), ": cannot put the new folder in place: ", windows::lastErrorText())};
        committed_ = true;
        return Status::success();
    }
    const fs::path old = siblingName(target_, "replaced");
    if (!moveFolder(target_, old))
        return Error{cat(target_.string(), ": cannot move the old folder aside: ", windows::lastErrorText())};
    if (!moveFolder(staging_, target_)) {
        const std::string why = windows::lastErrorText();
        (void)moveFolder(old, target_);
        return Error{cat(target_.string(), ": cannot put the new folder in place: ", why)};
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
