// fxlab-handout: every lesson as a page a student keeps after class (common/app/handout_build.hpp).
// The whole output folder appears at once when everything is written, or not at all.
#include <csignal>
#include <iostream>

#include "app/handout_build.hpp"
#include "app/handout_options.hpp"
#include "app/process_start.hpp"
#include "base/fatal_error.hpp"
#include "base/log.hpp"
#include "base/output_folder.hpp"

namespace {

volatile std::sig_atomic_t interrupted = 0;

void onSignal(int) {
    interrupted = 1;
}

}  // namespace

int main(int argc, char** argv) {
    using namespace fx::handout;
    fx::installFatalErrorHandler("fxlab-handout");
    auto line = parseCommandLine(fx::programArguments(argc, argv));
    if (!line) {
        std::cerr << "fxlab-handout: " << line.error() << "\n";
        return 2;
    }
    if (line->help) {
        std::cout << usage();
        return 0;
    }
    // Ctrl-C stops the lesson being captured too (one process group); a stop sent to this process
    // alone ends the run after the lesson in progress. Either way the unfinished folder is removed.
    std::signal(SIGINT, onSignal);
    std::signal(SIGTERM, onSignal);
    line->options.progress = [](const std::string& message) {
        std::cerr << "fxlab-handout: " << message << "\n";
    };

    const std::filesystem::path out = line->out.empty() ? defaultOut(*line) : line->out;
    auto staged = fx::StagedFolder::begin(out, line->force);
    if (!staged) {
        std::cerr << "fxlab-handout: " << staged.error() << "\n";
        return 1;
    }
    const auto& folder = (*staged)->path();
    const bool several = line->lessons.size() > 1;
    std::vector<ContentsEntry> entries;
    for (const auto& lesson : line->lessons) {
        const std::filesystem::path lessonFolder = several ? folder / *lessonFolderOf(lesson) : folder;
        fx::Doing doing(fx::cat("writing the handout of ", lesson.string()));
        auto entry = writeLessonHandout(lesson, line->options, lessonFolder);
        if (!entry || interrupted) {
            std::cerr << "fxlab-handout: " << (entry ? std::string("interrupted") : entry.error())
                      << "\nfxlab-handout: nothing was written at " << out.string() << "\n";
            return 1;
        }
        entries.push_back(*entry);
    }
    if (several) {
        if (auto s = writeContents(entries, line->options.languages, folder); !s) {
            std::cerr << "fxlab-handout: " << s.error() << "\nfxlab-handout: nothing was written at "
                      << out.string() << "\n";
            return 1;
        }
    }
    if (auto s = (*staged)->commit(); !s) {
        std::cerr << "fxlab-handout: " << s.error() << "\n";
        return 1;
    }
    std::cout << "handout written to " << out.string() << "/"
              << pageFileFor(line->options.languages.front(), line->options.languages) << "\n";
    return 0;
}
