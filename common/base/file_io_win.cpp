// The write rule and bounded reads on Windows (base/file_io.hpp), through the wide functions: paths
// are UTF-8 inside fxlab and UTF-16 here, so a Japanese folder name is the same name on disk.
//  - A link on Windows is a reparse point (a symbolic link or a junction): opened with
//    FILE_FLAG_OPEN_REPARSE_POINT it is seen as itself, and refused, never followed.
//  - Each folder of the chain is held open, without FILE_SHARE_DELETE, until the file is in place:
//    while it is held, Windows lets nobody rename or remove it, so no link can be swapped in for a
//    folder that was checked (the guarantee POSIX gets from openat and O_NOFOLLOW).
//  - MoveFileExW(MOVEFILE_REPLACE_EXISTING) replaces the target's name atomically on one volume.
//  - Names Windows keeps for devices (CON, NUL, COM1, LPT1 ..., with any extension) and names ending in
//    a dot or a space (which Windows silently drops) are refused before anything is made.
#include "base/file_io.hpp"
#include "base/file_io_rules.hpp"

#include <windows.h>

#include <algorithm>
#include <cwctype>
#include <optional>
#include <vector>

#include "base/log.hpp"
#include "base/windows_text.hpp"

namespace fx {
namespace {

namespace fs = std::filesystem;

class Handle {
public:
    explicit Handle(HANDLE h = INVALID_HANDLE_VALUE) : h_(h) {}
    ~Handle() {
        if (valid()) CloseHandle(h_);
    }
    Handle(Handle&& other) noexcept : h_(std::exchange(other.h_, INVALID_HANDLE_VALUE)) {}
    Handle& operator=(Handle&&) = delete;
    Handle(const Handle&) = delete;
    bool valid() const { return h_ != INVALID_HANDLE_VALUE && h_ != nullptr; }
    HANDLE get() const { return h_; }
    // Closes now and reports whether the close itself worked.
    bool close() {
        const bool ok = CloseHandle(h_) != 0;
        h_ = INVALID_HANDLE_VALUE;
        return ok;
    }

private:
    HANDLE h_;
};

// Why a name Windows reads specially may not be a file or folder name, or nothing.
std::optional<std::string> reservedName(const fs::path& part) {
    const std::wstring& name = part.native();
    if (name.empty() || name == L"." || name == L"..") return std::nullopt;
    if (name.back() == L'.' || name.back() == L' ')
        return "ends in a dot or a space, which Windows drops from names (choose another name)";
    std::wstring stem = name.substr(0, name.find(L'.'));
    while (!stem.empty() && stem.back() == L' ') stem.pop_back();
    std::transform(stem.begin(), stem.end(), stem.begin(),
                   [](wchar_t c) { return wchar_t(std::towupper(c)); });
    static const wchar_t* const kDevices[] = {L"CON", L"PRN", L"AUX", L"NUL", L"CONIN$", L"CONOUT$"};
    bool device = std::find(std::begin(kDevices), std::end(kDevices), stem) != std::end(kDevices);
    if (stem.size() == 4 && (stem.starts_with(L"COM") || stem.starts_with(L"LPT")) && stem[3] >= L'1' &&
        stem[3] <= L'9')
        device = true;
    if (device)
        return cat("\"", part.string(),
                   "\" is the name of a Windows device, not of a file (choose another name)");
    return std::nullopt;
}

std::optional<std::string> reservedPart(const fs::path& name) {
    for (const fs::path& part : name)
        if (auto why = reservedName(part)) return why;
    return std::nullopt;
}

// What is at `path` (not following a link), or nothing when nothing is there.
struct Found {
    DWORD attributes = 0;
    DWORD type = FILE_TYPE_DISK;
};
Result<std::optional<Found>> lookAt(const fs::path& path, const fs::path& shown) {
    HANDLE h = CreateFileW(path.c_str(), FILE_READ_ATTRIBUTES,
                           FILE_SHARE_READ | FILE_SHARE_WRITE | FILE_SHARE_DELETE, nullptr, OPEN_EXISTING,
                           FILE_FLAG_BACKUP_SEMANTICS | FILE_FLAG_OPEN_REPARSE_POINT, nullptr);
    if (h == INVALID_HANDLE_VALUE) {
        const DWORD error = GetLastError();
        if (error == ERROR_FILE_NOT_FOUND || error == ERROR_PATH_NOT_FOUND) return std::optional<Found>();
        return Error{cat(shown.string(), ": cannot look at it (", windows::errorText(error), ")")};
    }
    Handle handle(h);
    BY_HANDLE_FILE_INFORMATION info{};
    if (!GetFileInformationByHandle(h, &info))
        return Error{cat(shown.string(), ": cannot look at it (", windows::lastErrorText(), ")")};
    Found found{info.dwFileAttributes, GetFileType(h)};
    // Wine reports a symbolic link's reparse attribute by name only, not through the link's own handle.
    if (const DWORD byName = GetFileAttributesW(path.c_str()); byName != INVALID_FILE_ATTRIBUTES)
        found.attributes |= byName & FILE_ATTRIBUTE_REPARSE_POINT;
    return std::optional<Found>(found);
}

std::string describe(const Found& found) {
    if (found.attributes & FILE_ATTRIBUTE_REPARSE_POINT)
        return "a link (a reparse point: symbolic link or junction)";
    if (found.attributes & FILE_ATTRIBUTE_DIRECTORY) return "a folder";
    if (found.type == FILE_TYPE_CHAR) return "a device";
    if (found.type == FILE_TYPE_PIPE) return "a pipe";
    if (found.type == FILE_TYPE_DISK) return "a regular file";
    return "not a regular file";
}

// Why `found` at `shown` may not be replaced, or nothing when it may (a regular file).
std::optional<Error> refusedTarget(const fs::path& shown, const Found& found) {
    if (found.attributes & FILE_ATTRIBUTE_REPARSE_POINT)
        return Error{cat(shown.string(), ": is ", describe(found),
                         "; fxlab never writes through a link (remove it or choose another name)")};
    if (found.attributes & FILE_ATTRIBUTE_DIRECTORY)
        return Error{cat(shown.string(), ": is a folder; give a file name")};
    if (found.type != FILE_TYPE_DISK)
        return Error{cat(shown.string(), ": is ", describe(found),
                         "; fxlab writes only regular files (choose a file name)")};
    return std::nullopt;
}

// Opens a folder to hold it: nobody may rename or remove it while the handle lives.
Result<Handle> holdFolder(const fs::path& path, const fs::path& shown) {
    HANDLE h = CreateFileW(path.c_str(), FILE_READ_ATTRIBUTES, FILE_SHARE_READ | FILE_SHARE_WRITE, nullptr,
                           OPEN_EXISTING, FILE_FLAG_BACKUP_SEMANTICS | FILE_FLAG_OPEN_REPARSE_POINT, nullptr);
    if (h == INVALID_HANDLE_VALUE)
        return Error{cat(shown.string(), ": cannot open the folder (", windows::lastErrorText(), ")")};
    return Handle(h);
}

// Makes and holds the chosen folder and each folder of `subfolders` below it; none below the chosen
// one may be a link. Returns the real path of the folder that holds the file.
Result<fs::path> openFolderChain(const fs::path& folder, const fs::path& subfolders, fs::path& shown,
                                 std::vector<Handle>& held) {
    const fs::path top = folder.empty() ? fs::path(".") : folder;
    std::error_code ec;
    fs::create_directories(top, ec);
    if (ec) return Error{cat(top.string(), ": cannot create folder (", ec.message(), ")")};
    // The chosen folder may be reached through links the user named: hold the folder they lead to.
    HANDLE h = CreateFileW(top.c_str(), FILE_READ_ATTRIBUTES, FILE_SHARE_READ | FILE_SHARE_WRITE, nullptr,
                           OPEN_EXISTING, FILE_FLAG_BACKUP_SEMANTICS, nullptr);
    if (h == INVALID_HANDLE_VALUE)
        return Error{cat(top.string(), ": cannot open the folder (", windows::lastErrorText(), ")")};
    held.emplace_back(h);
    fs::path at = top;
    shown = folder;
    for (const fs::path& part : subfolders) {
        if (part.empty() || part == ".") continue;
        shown /= part;
        at /= part;
        if (!CreateDirectoryW(at.c_str(), nullptr) && GetLastError() != ERROR_ALREADY_EXISTS)
            return Error{cat(shown.string(), ": cannot create folder (", windows::lastErrorText(), ")")};
        auto found = lookAt(at, shown);
        if (!found) return Error{found.error()};
        if (!*found) return Error{cat(shown.string(), ": vanished while it was made")};
        const Found& f = **found;
        if (f.attributes & FILE_ATTRIBUTE_REPARSE_POINT)
            return Error{cat(shown.string(), ": is ", describe(f), "; fxlab writes only inside ",
                             folder.string(), " and never follows a link out of it")};
        if (!(f.attributes & FILE_ATTRIBUTE_DIRECTORY))
            return Error{cat(shown.string(), ": is ", describe(f), ", not a folder")};
        auto hold = holdFolder(at, shown);
        if (!hold) return Error{hold.error()};
        // A link swapped in between the look and the hold: the held handle says so.
        BY_HANDLE_FILE_INFORMATION info{};
        if (!GetFileInformationByHandle(hold->get(), &info) ||
            (info.dwFileAttributes & FILE_ATTRIBUTE_REPARSE_POINT) ||
            !(info.dwFileAttributes & FILE_ATTRIBUTE_DIRECTORY))
            return Error{cat(shown.string(),
                             ": changed while it was checked; fxlab never follows a link out of ",
                             folder.string())};
        held.push_back(std::move(*hold));
    }
    return at;
}

bool writeAll(HANDLE h, std::span<const std::byte> bytes) {
    const std::byte* p = bytes.data();
    std::size_t left = bytes.size();
    while (left > 0) {
        DWORD written = 0;
        const DWORD chunk = DWORD(std::min<std::size_t>(left, 1u << 30));
        if (!WriteFile(h, p, chunk, &written, nullptr) || written == 0) return false;
        p += written;
        left -= written;
    }
    return true;
}

}  // namespace

Result<std::string> readFile(const fs::path& path, FileLimit limit) {
    // Reads follow links (the user may keep a scene anywhere); only a regular file is read.
    HANDLE h = CreateFileW(path.c_str(), GENERIC_READ, FILE_SHARE_READ | FILE_SHARE_WRITE | FILE_SHARE_DELETE,
                           nullptr, OPEN_EXISTING, FILE_FLAG_BACKUP_SEMANTICS, nullptr);
    if (h == INVALID_HANDLE_VALUE)
        return Error{cat(path.string(), ": cannot open file (", windows::lastErrorText(), ")")};
    Handle file(h);
    BY_HANDLE_FILE_INFORMATION info{};
    const DWORD type = GetFileType(h);
    if (type != FILE_TYPE_DISK || !GetFileInformationByHandle(h, &info) ||
        (info.dwFileAttributes & FILE_ATTRIBUTE_DIRECTORY))
        return Error{cat(path.string(), ": is ", describe(Found{info.dwFileAttributes, type}), ", not a ",
                         limit.kind, " (only regular files are read)")};
    auto overLimit = [&](std::string_view size) {
        return Error{cat(path.string(), ": ", size, " is over the limit for a ", limit.kind, " (",
                         describeByteCount(limit.maxBytes), ")")};
    };
    const std::uint64_t size = (std::uint64_t(info.nFileSizeHigh) << 32) | info.nFileSizeLow;
    if (size > limit.maxBytes) return overLimit(cat(size, " bytes"));
    // The size is a hint (a file may grow while read): read up to one byte past the limit to know.
    std::string text(std::min<std::size_t>(std::size_t(size) + 1, limit.maxBytes + 1), '\0');
    std::size_t used = 0;
    for (;;) {
        if (used == text.size()) {
            if (text.size() > limit.maxBytes) return overLimit("the file");
            text.resize(std::min(text.size() * 2 + 4096, limit.maxBytes + 1));
        }
        DWORD n = 0;
        const DWORD want = DWORD(std::min<std::size_t>(text.size() - used, 1u << 30));
        if (!ReadFile(h, text.data() + used, want, &n, nullptr))
            return Error{cat(path.string(), ": read failed (", windows::lastErrorText(), ")")};
        if (n == 0) break;
        used += n;
    }
    if (used > limit.maxBytes) return overLimit("the file");
    text.resize(used);
    return text;
}

Status writeFileInFolder(const fs::path& folder, const fs::path& name, std::span<const std::byte> bytes) {
    const fs::path shownTarget = folder / name;
    if (auto why = detail::outsideTheFolder(name)) return Error{cat(shownTarget.string(), ": ", *why)};
    if (auto why = reservedPart(name)) return Error{cat(shownTarget.string(), ": ", *why)};
    fs::path shown;
    std::vector<Handle> held;
    auto opened = openFolderChain(folder, name.parent_path(), shown, held);
    if (!opened) return Error{cat(shownTarget.string(), ": cannot write: ", opened.error())};
    const fs::path target = *opened / name.filename();
    shown /= name.filename();

    auto found = lookAt(target, shown);
    if (!found) return Error{found.error()};
    if (*found)
        if (auto refused = refusedTarget(shown, **found)) return *refused;

    // The temporary file sits beside the target so that the move stays on one volume. CREATE_NEW never
    // opens anything planted at the temporary name.
    const fs::path temp = *opened / cat(name.filename().string(), ".tmp", GetCurrentProcessId());
    auto create = [&] {
        return CreateFileW(temp.c_str(), GENERIC_WRITE, 0, nullptr, CREATE_NEW,
                           FILE_ATTRIBUTE_NORMAL | FILE_FLAG_OPEN_REPARSE_POINT, nullptr);
    };
    HANDLE h = create();
    if (h == INVALID_HANDLE_VALUE && GetLastError() == ERROR_FILE_EXISTS) {  // left by a process with our id
        DeleteFileW(temp.c_str());
        h = create();
    }
    if (h == INVALID_HANDLE_VALUE)
        return Error{cat(shown.string(), ": cannot write (", windows::lastErrorText(), ")")};
    Handle file(h);
    bool ok = writeAll(h, bytes) && FlushFileBuffers(h);
    std::string why = ok ? std::string() : windows::lastErrorText();
    if (!file.close() && ok) {
        ok = false;
        why = windows::lastErrorText();
    }
    if (!ok) {
        DeleteFileW(temp.c_str());
        return Error{cat(shown.string(), ": write failed (", why, ")")};
    }
    // The move replaces the name that is there now (a link planted since the look included, never
    // written through) in one step.
    if (!MoveFileExW(temp.c_str(), target.c_str(), MOVEFILE_REPLACE_EXISTING | MOVEFILE_WRITE_THROUGH)) {
        why = windows::lastErrorText();
        DeleteFileW(temp.c_str());
        return Error{cat(shown.string(), ": cannot move the finished file into place (", why, ")")};
    }
    return Status::success();
}

Status makeFolderIn(const fs::path& folder, const fs::path& name) {
    if (auto why = detail::outsideTheFolder(name)) return Error{cat((folder / name).string(), ": ", *why)};
    if (auto why = reservedPart(name)) return Error{cat((folder / name).string(), ": ", *why)};
    fs::path shown;
    std::vector<Handle> held;
    auto opened = openFolderChain(folder, name, shown, held);
    if (!opened) return Error{opened.error()};
    return Status::success();
}

Status writeStandardOutput(std::string_view text) {
    std::fflush(stdout);  // what the C runtime holds goes first
    if (!writeAll(GetStdHandle(STD_OUTPUT_HANDLE), std::as_bytes(std::span(text.data(), text.size()))))
        return Error{cat("standard output: write failed (", windows::lastErrorText(), ")")};
    return Status::success();
}

}  // namespace fx
