#include "base/file_io.hpp"

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "base/log.hpp"

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

// /dev/stdout and friends: a path that stands for a descriptor this process already has open.
bool namesOpenDescriptor(const fs::path& path) {
    std::string text = path.lexically_normal().string();
    for (std::string_view prefix : {"/dev/stdout", "/dev/stderr", "/dev/fd/", "/proc/self/fd/"})
        if (text.starts_with(prefix)) return true;
    return text.starts_with("/proc/") && text.find("/fd/") != std::string::npos;
}

Status writeThrough(const fs::path& path, std::span<const std::byte> bytes, bool append) {
    // O_NONBLOCK: opening a FIFO that nobody reads fails (ENXIO) instead of waiting for a reader.
    int flags = O_WRONLY | O_NOCTTY | O_CLOEXEC | O_NONBLOCK | (append ? O_APPEND : 0);
    Descriptor fd(::open(path.c_str(), flags));
    if (fd.get() < 0) {
        int saved = errno;
        if (saved == ENXIO) return Error{cat(path.string(), ": cannot write (nothing is reading it)")};
        return Error{cat(path.string(), ": cannot write (", reason(saved), ")")};
    }
    // Back to blocking writes: a pipe that is full should wait for its reader, not fail.
    int current = ::fcntl(fd.get(), F_GETFL);
    if (current >= 0) ::fcntl(fd.get(), F_SETFL, current & ~O_NONBLOCK);
    if (int saved = writeAll(fd.get(), bytes); saved != 0)
        return Error{cat(path.string(), ": write failed (", reason(saved), ")")};
    if (fd.close() != 0) return Error{cat(path.string(), ": write failed (", reason(errno), ")")};
    return Status::success();
}

Status replaceAtomically(const fs::path& path, std::span<const std::byte> bytes) {
    std::error_code ec;
    if (path.has_parent_path()) {
        fs::create_directories(path.parent_path(), ec);
        if (ec) return Error{cat(path.string(), ": cannot create folder (", ec.message(), ")")};
    }
    // The temporary file sits beside the target so that rename() stays on one file system. O_EXCL
    // never follows a link planted at the temporary name.
    fs::path temp = path;
    temp += cat(".tmp", ::getpid());
    int flags = O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC;
    int raw = ::open(temp.c_str(), flags, 0666);
    if (raw < 0 && errno == EEXIST) {  // left over from a process with the same id that died
        ::unlink(temp.c_str());
        raw = ::open(temp.c_str(), flags, 0666);
    }
    if (raw < 0) return Error{cat(path.string(), ": cannot write (", reason(errno), ")")};
    Descriptor fd(raw);
    int saved = writeAll(fd.get(), bytes);
    if (saved == 0 && ::fsync(fd.get()) != 0) saved = errno;
    if (fd.close() != 0 && saved == 0) saved = errno;
    if (saved != 0) {
        ::unlink(temp.c_str());
        return Error{cat(path.string(), ": write failed (", reason(saved), ")")};
    }
    if (::rename(temp.c_str(), path.c_str()) != 0) {
        saved = errno;
        ::unlink(temp.c_str());
        return Error{cat(path.string(), ": cannot move the finished file into place (", reason(saved), ")")};
    }
    return Status::success();
}

}  // namespace

std::string describeByteCount(std::size_t bytes) {
    if (bytes >= file_limits::kMiB && bytes % file_limits::kMiB == 0)
        return cat(bytes / file_limits::kMiB, " MiB");
    if (bytes >= 1024 && bytes % 1024 == 0) return cat(bytes / 1024, " KiB");
    return cat(bytes, " bytes");
}

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

Result<std::string> readTextFile(const fs::path& path) {
    return readFile(path, file_limits::text);
}

Status writeFileAtomically(const fs::path& path, std::span<const std::byte> bytes) {
    if (path.empty()) return Error{"cannot write a file with an empty name"};
    if (namesOpenDescriptor(path)) return writeThrough(path, bytes, true);
    struct stat info {};
    if (::stat(path.c_str(), &info) == 0) {  // follows links: what is there in the end
        if (S_ISDIR(info.st_mode)) return Error{cat(path.string(), ": is a folder; give a file name")};
        if (!S_ISREG(info.st_mode)) return writeThrough(path, bytes, false);
    }
    // A link (or chain of links) is replaced at its end, so the link itself survives. A dangling link
    // creates its target.
    struct stat link {};
    if (::lstat(path.c_str(), &link) == 0 && S_ISLNK(link.st_mode)) {
        std::error_code ec;
        fs::path target = fs::weakly_canonical(path, ec);
        if (ec) return Error{cat(path.string(), ": cannot follow the link (", ec.message(), ")")};
        return replaceAtomically(target, bytes);
    }
    return replaceAtomically(path, bytes);
}

Status writeFileAtomically(const fs::path& path, std::string_view text) {
    return writeFileAtomically(path, std::as_bytes(std::span(text.data(), text.size())));
}

}  // namespace fx
