#include "base/file_io.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include "base/log.hpp"

namespace fx {

Result<std::string> readTextFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return Error{cat(path.string(), ": cannot open file (", std::strerror(errno), ")")};
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) return Error{cat(path.string(), ": read failed")};
    return text.str();
}

Status writeFileAtomically(const std::filesystem::path& path, std::span<const std::byte> bytes) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (path.has_parent_path()) {
        fs::create_directories(path.parent_path(), ec);
        if (ec) return Error{cat(path.string(), ": cannot create folder (", ec.message(), ")")};
    }
    // The temporary file sits beside the target so that rename() stays on one file system.
    fs::path temp = path;
    temp += cat(".tmp", ::getpid());
    std::FILE* file = std::fopen(temp.c_str(), "wb");
    if (!file) return Error{cat(path.string(), ": cannot write (", std::strerror(errno), ")")};
    bool written = std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size();
    written = (std::fflush(file) == 0) && written;
    written = (::fsync(::fileno(file)) == 0) && written;
    written = (std::fclose(file) == 0) && written;
    if (!written) {
        fs::remove(temp, ec);
        return Error{cat(path.string(), ": write failed")};
    }
    fs::rename(temp, path, ec);
    if (ec) {
        fs::remove(temp, ec);
        return Error{cat(path.string(), ": cannot move the finished file into place (", ec.message(), ")")};
    }
    return Status::success();
}

Status writeFileAtomically(const std::filesystem::path& path, std::string_view text) {
    return writeFileAtomically(path, std::as_bytes(std::span(text.data(), text.size())));
}

}  // namespace fx
