#include "app/bench_mode.hpp"

#include <iostream>

#include "app/bench.hpp"
#include "app/lesson_listing.hpp"
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
    int step = !o.step && lesson.benchStep() >= 0 ? lesson.benchStep() : s.step;
    SweepResult result = sweepKnobs(lesson, s.params, renderer, context,
                                    {o.benchKnob, o.benchFrames, o.benchValues}, s.exe, step);
    std::cout << describeSweep(result);
    int exitCode = 0;
    if (auto written = writeBenchOutputs(result, dir); !written) {
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
