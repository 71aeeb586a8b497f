#pragma once
// A folder written whole or not at all: everything goes into a hidden sibling of the target
// (".<name>.partial-<pid>"), which replaces the target by a rename once it is complete. If the work
// fails, or the program leaves before commit(), the sibling is removed and the target is as it was.
//
// The target may be missing or an empty folder. A folder with something in it is refused unless
// `replace` is set (the command line's --force) and the folder holds the marker an earlier StagedFolder
// left (kStagedFolderMarker, a regular file): only a folder fxlab wrote is ever replaced, never one of
// the user's. A symbolic link, a file, a device or a FIFO is always refused, so nothing that is not a
// folder is ever replaced and no link is followed.
#include <filesystem>
#include <memory>

#include "base/result.hpp"

namespace fx {

// The file every staged folder holds, saying that fxlab wrote it (and so may replace it).
inline constexpr const char* kStagedFolderMarker = ".fxlab-handout";

class StagedFolder {
public:
    // Checks the target and makes the hidden sibling (and any missing parent folders). The error
    // names the target and the reason ("out/h: a folder with files in it; --force replaces it").
    static Result<std::unique_ptr<StagedFolder>> begin(const std::filesystem::path& target, bool replace);
    ~StagedFolder();  // removes the sibling unless committed
    StagedFolder(const StagedFolder&) = delete;
    StagedFolder& operator=(const StagedFolder&) = delete;

    // Where to write: the hidden sibling.
    const std::filesystem::path& path() const { return staging_; }
    const std::filesystem::path& target() const { return target_; }

    // Checks the target again (it may have changed meanwhile) and puts the sibling in its place. A
    // replaced folder is removed only once the new one is in place.
    Status commit();

private:
    StagedFolder(std::filesystem::path target, std::filesystem::path staging, bool replace);
    std::filesystem::path target_, staging_;
    bool replace_ = false;
    bool committed_ = false;
};

}  // namespace fx
