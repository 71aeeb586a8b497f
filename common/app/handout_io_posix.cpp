// findProgram on POSIX: PATH's folders split at ':', the first executable file of that name.
#include "app/handout_io.hpp"

#include <cstdlib>

#include <unistd.h>

namespace fx::handout {

namespace fs = std::filesystem;

fs::path findProgram(const std::string& name) {
    const char* path = std::getenv("PATH");
    const std::string dirs = path ? path : "/usr/bin:/bin";
    std::size_t start = 0;
    while (start <= dirs.size()) {
        std::size_t end = dirs.find(':', start);
        if (end == std::string::npos) end = dirs.size();
        const fs::path candidate = fs::path(dirs.substr(start, end - start)) / name;
        if (end > start && ::access(candidate.c_str(), X_OK) == 0) return candidate;
        start = end + 1;
    }
    return {};
}

}  // namespace fx::handout
