#include "base/file_io.hpp"
#include "base/file_io_rules.hpp"

#include <cerrno>
#include <cstring>
#include <optional>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "base/log.hpp"
#include "base/stale_temporaries.hpp"

namespace fx {
namespace {

namespace fs = std::filesystem;

// strerror of a saved errno: the caller saves it right after the call that failed, before any other
// call (a close, a remove) can overwrite it.
std::string reason(int savedErrno) {
    return std::strerror(savedErrno);
}

// Closes a descriptor on every path out of a function.
class Descriptor {
public:
    explicit Descriptor(int fd) : fd_(fd) {}
    ~Descriptor() {
        if (fd_ >= 0) ::close(fd_);
    }
    Descriptor(const Descriptor&) = delete;
    Descriptor& operator=(const Descriptor&) = delete;
    int get() const { return fd_; }
    // Closes now and reports close's own failure (a write-back error shows up here on some systems).
    int close() {
        int result = ::close(fd_);
        fd_ = -1;
        return result;
    }

private:
    int fd_;
};

std::string describeFileType(mode_t mode) {
    if (S_ISDIR(mode)) return "a folder";
    if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISSOCK(mode)) return "a socket";
    if (S_ISLNK(mode)) return "a symbolic link";
    if (S_ISREG(mode)) return "a regular file";
    return "not a regular file";
}

// Writes all of `bytes`; on failure returns the errno of the failing write.
int writeAll(int fd, std::span<const std::byte> bytes) {
    const std::byte* p = bytes.data();
    std::size_t left = bytes.size();
    while (left > 0) {
        ssize_t n = ::write(fd, p, left);
        if (n < 0) {
            if (errno == EINTR) continue;
            return errno;
        }
        if (n == 0) return EIO;
        p += n;
        left -= std::size_t(n);
    }
    return 0;
}

// Why `mode` at `shown` may not be replaced, or nothing when it may (a regular file).
std::optional<Error> refusedTarget(const fs::path& shown, mode_t mode) {
    if (S_ISREG(mode)) return std::nullopt;
    if (S_ISLNK(mode))
        return Error{cat(
            shown.string(),
            ": is a symbolic link; fxlab never writes through a link (remove it or choose another name)")};
    if (S_ISDIR(mode)) return Error{cat(shown.string(), ": is a folder; give a file name")};
    return Error{cat(shown.string(), ": is ", describeFileType(mode),
                     "; fxlab writes only regular files (choose a file name)")};
}

// Opens the chosen folder (creating it), then each folder of `name` below it without following a link.
// Returns the descriptor of the folder that holds the file; `shown` tracks the path for messages.
Result<int> openFolderChain(const fs::path& folder, const fs::path& subfolders, fs::path& shown) {
    const fs::path top = folder.empty() ? fs::path(".") : folder;
    std::error_code ec;
    fs::create_directories(top, ec);
    if (ec) return Error{cat(top.string(), ": cannot create folder (", ec.message(), ")")};
    int fd = ::open(top.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return Error{cat(top.string(), ": cannot open the folder (", reason(errno), ")")};
    shown = folder;
    for (const fs::path& part : subfolders) {
        if (part.empty() || part == ".") continue;
        shown /= part;
        Descriptor parent(fd);
        if (::mkdirat(parent.get(), part.c_str(), 0777) != 0 && errno != EEXIST)
            return Error{cat(shown.string(), ": cannot create folder (", reason(errno), ")")};
        struct stat info {};
        if (::fstatat(parent.get(), part.c_str(), &info, AT_SYMLINK_NOFOLLOW) != 0)
            return Error{cat(shown.string(), ": cannot create folder (", reason(errno), ")")};
        if (!S_ISDIR(info.st_mode)) {
            if (S_ISLNK(info.st_mode))
                return Error{cat(shown.string(), ": is a symbolic link; fxlab writes only inside ",
                                 folder.string(), " and never follows a link out of it")};
            return Error{cat(shown.string(), ": is ", describeFileType(info.st_mode), ", not a folder")};
        }
        // O_NOFOLLOW: a link swapped in since the check above is refused, not followed.
        fd = ::openat(parent.get(), part.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
        if (fd < 0) return Error{cat(shown.string(), ": cannot open the folder (", reason(errno), ")")};
    }
    return fd;
}

}  // namespace

Result<std::string> readFile(const fs::path& path, FileLimit limit) {
    // O_NONBLOCK so that opening a FIFO returns at once; the type check below refuses it unread.
    Descriptor fd(::open(path.c_str(), O_RDONLY | O_NOCTTY | O_CLOEXEC | O_NONBLOCK));
    if (fd.get() < 0) return Error{cat(path.string(), ": cannot open file (", reason(errno), ")")};
    struct stat info {};
    if (::fstat(fd.get(), &info) != 0)
        return Error{cat(path.string(), ": cannot read (", reason(errno), ")")};
    if (!S_ISREG(info.st_mode))
        return Error{cat(path.string(), ": is ", describeFileType(info.st_mode), ", not a ", limit.kind,
                         " (only regular files are read)")};
    auto overLimit = [&](std::string_view size) {
        return Error{cat(path.string(), ": ", size, " is over the limit for a ", limit.kind, " (",
                         describeByteCount(limit.maxBytes), ")")};
    };
    if (info.st_size > 0 && std::uintmax_t(info.st_size) > limit.maxBytes)
        return overLimit(cat(info.st_size, " bytes"));
    // The size stat gives is a hint (files in /proc say 0, a file may grow while read): read up to one
    // byte past the limit to know for sure.
    std::string text;
    text.resize(std::min<std::size_t>(std::size_t(std::max<off_t>(info.st_size, 0)) + 1, limit.maxBytes + 1));
    std::size_t used = 0;
    for (;;) {
        if (used == text.size()) {
            if (text.size() > limit.maxBytes) return overLimit("the file");
            text.resize(std::min(text.size() * 2 + 4096, limit.maxBytes + 1));
        }
        ssize_t n = ::read(fd.get(), text.data() + used, text.size() - used);
        if (n < 0) {
            if (errno == EINTR) continue;
            return Error{cat(path.string(), ": read failed (", reason(errno), ")")};
        }
        if (n == 0) break;
        used += std::size_t(n);
    }
    if (used > limit.maxBytes) return overLimit("the file");
    text.resize(used);
    return text;
}

Status writeFileInFolder(const fs::path& folder, const fs::path& name, std::span<const std::byte> bytes) {
    const fs::path shownTarget = folder / name;
    if (auto why = detail::outsideTheFolder(name)) return Error{cat(shownTarget.string(), ": ", *why)};
    fs::path shown;
    auto opened = openFolderChain(folder, name.parent_path(), shown);
    if (!opened) return Error{cat(shownTarget.string(), ": cannot write: ", opened.error())};
    Descriptor dir(*opened);
    const std::string leaf = name.filename().string();
    shown /= leaf;

    struct stat info {};
    if (::fstatat(dir.get(), leaf.c_str(), &info, AT_SYMLINK_NOFOLLOW) == 0) {
        if (auto refused = refusedTarget(shown, info.st_mode)) return *refused;
    } else if (errno != ENOENT) {
        return Error{cat(shown.string(), ": cannot write (", reason(errno), ")")};
    }

    (void)removeStaleTemporaries(dir.get(), leaf);  // of a writer killed before its rename
    // The temporary file sits beside the target so that the rename stays on one file system. O_EXCL
    // and O_NOFOLLOW never follow anything planted at the temporary name.
    const std::string temp = cat(leaf, ".tmp", ::getpid());
    const int flags = O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC;
    int raw = ::openat(dir.get(), temp.c_str(), flags, 0666);
    if (raw < 0 && errno == EEXIST) {  // left over from a process with the same id that died
        ::unlinkat(dir.get(), temp.c_str(), 0);
        raw = ::openat(dir.get(), temp.c_str(), flags, 0666);
    }
    if (raw < 0) return Error{cat(shown.string(), ": cannot write (", reason(errno), ")")};
    Descriptor fd(raw);
    int saved = writeAll(fd.get(), bytes);
    if (saved == 0 && ::fsync(fd.get()) != 0) saved = errno;
    if (fd.close() != 0 && saved == 0) saved = errno;
    if (saved != 0) {
        ::unlinkat(dir.get(), temp.c_str(), 0);
        return Error{cat(shown.string(), ": write failed (", reason(saved), ")")};
    }
    // rename replaces whatever name is there now, a link planted since the check included, and never
    // writes through it.
    if (::renameat(dir.get(), temp.c_str(), dir.get(), leaf.c_str()) != 0) {
        saved = errno;
        ::unlinkat(dir.get(), temp.c_str(), 0);
        return Error{cat(shown.string(), ": cannot move the finished file into place (", reason(saved), ")")};
    }
    return Status::success();
}

Status makeFolderIn(const fs::path& folder, const fs::path& name) {
    if (auto why = detail::outsideTheFolder(name)) return Error{cat((folder / name).string(), ": ", *why)};
    fs::path shown;
    auto opened = openFolderChain(folder, name, shown);
    if (!opened) return Error{opened.error()};
    ::close(*opened);
    return Status::success();
}

Status writeStandardOutput(std::string_view text) {
    if (int saved = writeAll(STDOUT_FILENO, std::as_bytes(std::span(text.data(), text.size()))); saved != 0)
        return Error{cat("standard output: write failed (", reason(saved), ")")};
    return Status::success();
}

}  // namespace fx
