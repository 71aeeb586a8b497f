#pragma once
// What every fxlab program does first with its command line (process_start_posix.cpp,
// process_start_win.cpp): the arguments after the program's name, as UTF-8. POSIX: argv as it is.
// Windows: read from the wide command line (argv is in the ANSI code page, which cannot hold every
// name), and, since a lesson is a GUI program that opens no console when double-clicked, attached to
// the console of whoever started it from one, so that --help and messages still show there.
#include <string>
#include <vector>

namespace fx {

std::vector<std::string> programArguments(int argc, char** argv);

// Whether standard error is a terminal (a person watching), not a file or a pipe.
bool standardErrorIsTerminal();

}  // namespace fx
