#include "app/bench_mode.hpp"

#include <cstdio>
#include <iostream>

#include "app/bench.hpp"
#include "app/lesson_listing.hpp"
#include "app/process_start.hpp"
#include "base/log.hpp"
#include "gl/debug_output.hpp"

namespace fx {

namespace fs = std::filesystem;

int runBenchMode(RunSession& s, FrameRenderer& renderer, Context& context) {
    const RunOptions& o = s.options;
    Lesson& lesson = *s.lesson;
    if (!o.benchKnob.empty() && (!s.params.find(o.benchKnob) || !s.params.find(o.benchKnob)->knob)) {
        std::string knobs;
        for (auto* k : s.params.knobs()) knobs += (knobs.empty() ? "" : ", ") + k->name;
        log::error(s.exe, ": --knob: no quality knob named \"", o.benchKnob,
                   "\"; this lesson has: ", knobs.empty() ? "(none)" : knobs);
        return 2;
    }
    fs::path dir =
        o.benchOut.empty() ? fs::path("out") / "bench" / lessonFolderName(lesson.info()) : o.benchOut;
    if (const Size2D size = context.framebufferSize(); size.empty()) {
        // A minimised window draws nothing, so a sweep at 0 pixels would time nothing and write empty tables.
        log::error(
            s.exe, ": --bench at ", size.width, "x", size.height,
            ": nothing is drawn at that size, so there is nothing to time (--size needs both sides >= 1)");
        return 2;
    }
    if (s.params.knobs().empty()) {
        // Nothing to sweep: say so instead of printing an empty table.
        std::cout << noKnobsMessage(s.exe) << "\n";
        return 0;
    }
    int step = !o.step && lesson.benchStep() >= 0 ? lesson.benchStep() : s.step;
    SweepOptions options{o.benchKnob, o.benchFrames, o.benchValues, {}};
    // On a terminal, one line that says which setting is being measured (a sweep takes minutes).
    if (standardErrorIsTerminal()) {
        options.progress = [](const SweepProgress& p) {
            if (p.next.empty()) {
                std::fprintf(stderr, "\r\033[Kmeasured %d settings\n", p.total);
            } else {
                std::fprintf(stderr, "\r\033[K[%d/%d] measuring %s", p.done + 1, p.total, p.next.c_str());
            }
            std::fflush(stderr);
        };
    }
    SweepResult result = sweepKnobs(lesson, s.params, renderer, context, options, s.exe, step);
    std::cout << describeSweep(result);
    int exitCode = 0;
    if (auto written = writeBenchOutputs(result, dir, o.benchCost); !written) {
        log::error(written.error());
        exitCode = 1;
    } else {
        log::info("bench results written to ", dir.string(), "/");
    }
    if (gl::debugCounters().errors > 0) {
        log::error(gl::debugCounters().errors,
                   " GL error(s) during the bench: ", gl::debugCounters().lastError);
        exitCode = 1;
    }
    return exitCode;
}

}  // namespace fx
