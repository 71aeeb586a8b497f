#include "app/process_start.hpp"

#include <unistd.h>

namespace fx {

std::vector<std::string> programArguments(int argc, char** argv) {
    return std::vector<std::string>(argv + 1, argv + argc);
}

bool standardErrorIsTerminal() {
    return ::isatty(STDERR_FILENO) != 0;
}

}  // namespace fx
