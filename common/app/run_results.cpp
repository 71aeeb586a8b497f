#include "app/run_results.hpp"

#include "base/file_io.hpp"
#include "base/log.hpp"
#include "gl/debug_output.hpp"
#include "render/graph_dot.hpp"

namespace fx {

int writeRunResults(RunSession& s, const RunPlan& plan, Context& context, const gl::ProgramRegistry& programs,
                    RunRecord& record) {
    RunFacts& facts = record.facts;
    facts.size = context.framebufferSize();
    facts.step = s.step + 1;
    auto steps = s.lesson->steps();
    facts.stepTitle = s.step < int(steps.size()) ? steps[std::size_t(s.step)] : "";
    facts.glErrors = gl::debugCounters().errors;
    facts.glExpectedErrors = gl::debugCounters().expectedErrors;
    facts.glWarnings = gl::debugCounters().warnings;
    facts.lastGlError = gl::debugCounters().lastError;
    facts.shaderErrors = programs.errors();
    Facts lessonFacts;
    s.lesson->facts(lessonFacts, record.lastFrame);
    for (const Fact& f : lessonFacts.list()) facts.lessonFacts.emplace_back(f.name, f.value);
    for (const Param& p : s.params.all())
        facts.params.push_back({p.name, p.text(), std::string(toString(p.source()))});

    int exitCode = 0;
    if (!plan.captureDir.empty()) {
        if (auto written = writeCaptures(plan.captureDir, record.lastFinalBytes, record.lastTextures,
                                         s.options.captureFloat);
            !written) {
            log::error(written.error());
            exitCode = 1;
        } else {
            log::info("captures written to ", plan.captureDir.string(), "/ (final.png and ",
                      record.lastTextures.size(), " intermediate textures)");
        }
    }
    if (!plan.reportFile.empty()) {
        auto json =
            buildRunReport(facts, record.lastReport, record.lastTextures, record.lastFinal).dump(2) + "\n";
        if (auto written = writeFileAtomically(plan.reportFile, json); !written) {
            log::error(written.error());
            exitCode = 1;
        } else {
            log::info("report written to ", plan.reportFile.string());
        }
    }
    if (!s.options.graphFile.empty()) {
        if (auto written = writeFileAtomically(s.options.graphFile, toDot(record.lastReport)); !written) {
            log::error(written.error());
            exitCode = 1;
        } else {
            log::info("frame graph written to ", s.options.graphFile.string(), " (dot -Tpng draws it)");
        }
    }
    if (facts.glErrors > 0)
        log::error(facts.glErrors, " GL error(s) in this run; the last: ", facts.lastGlError);
    return exitCode;
}

}  // namespace fx
