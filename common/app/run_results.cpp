#include "app/run_results.hpp"
#include "base/fatal_error.hpp"
#include "base/json_text.hpp"

#include "base/file_io.hpp"
#include "base/log.hpp"
#include "base/words.hpp"
#include "gl/debug_output.hpp"
#include "image/png_file.hpp"
#include "render/graph_dot.hpp"

namespace fx {

namespace {

// --report and --graph: a file under the one rule (base/file_io.hpp), or standard output for "-".
Status writeOutput(const std::filesystem::path& path, std::string_view text) {
    return namesStandardOutput(path) ? writeStandardOutput(text) : writeFileAtomically(path, text);
}

nlohmann::ordered_json rectJson(const LayoutRect& r) {
    return {int(r.x), int(r.y), int(r.width), int(r.height)};
}

}  // namespace

nlohmann::ordered_json layoutJson(const PanelLayout& layout, Size2D window, float textScale) {
    nlohmann::ordered_json j;
    j["window"] = {window.width, window.height};
    j["textScale"] = textScale;
    j["picture"] = rectJson(layout.picture);
    j["lesson"] = rectJson(layout.lesson);
    j["frame"] = rectJson(layout.frame);
    j["inspector"] = rectJson(layout.inspector);
    return j;
}

std::string capturesWrittenMessage(const std::filesystem::path& dir, bool finalImage, bool picture,
                                   std::size_t textures, bool emptyFrame) {
    std::string what;
    if (finalImage)
        what = picture ? "final.png (the window), picture.png (the lesson's picture)" : "final.png";
    const std::string texturesText = cat(textures, " intermediate texture", textures == 1 ? "" : "s");
    const std::string why = emptyFrame ? "the frame was empty (0x0), so no picture was drawn"
                                       : "the run ended before its last frame (the window was closed)";
    if (!finalImage && textures == 0) return cat("nothing captured into ", dir.string(), "/: ", why);
    if (!finalImage)
        return cat("captures written to ", dir.string(), "/: ", texturesText, "; no final.png: ", why);
    return cat("captures written to ", dir.string(), "/: ", what, " and ", texturesText);
}

int writeRunResults(RunSession& s, const RunPlan& plan, Context& context, const gl::ProgramRegistry& programs,
                    RunRecord& record) {
    RunFacts& facts = record.facts;
    facts.size = context.framebufferSize();
    facts.step = s.step + 1;
    auto steps = s.lesson->steps();
    facts.stepTitle = s.step < int(steps.size()) ? steps[std::size_t(s.step)] : "";
    facts.glErrors = gl::debugCounters().errors;
    facts.glExpectedErrors = gl::debugCounters().expectedErrors;
    facts.glExpectedErrorsThisStep = facts.glExpectedErrors - record.expectedErrorsBeforeStep;
    facts.glWarnings = gl::debugCounters().warnings;
    facts.lastGlError = gl::debugCounters().lastError;
    facts.shaderErrors = programs.errors();
    Facts lessonFacts;
    s.lesson->facts(lessonFacts, record.lastFrame);
    for (const Fact& f : lessonFacts.list()) {
        facts.lessonFacts.emplace_back(f.name, f.value);
        if (f.shown) facts.shownFacts.emplace_back(f.shownLabel(), f.value);
    }
    for (const Param& p : s.params.all()) {
        ParamFact fact{p.name, p.text(), std::string(toString(p.source())), p.label(), {}, p.pinned};
        for (const auto& [step, value] : p.stepValues) {
            if (step != s.step) fact.changedInSteps.emplace_back(step + 1, p.valueText(value));
        }
        facts.params.push_back(fact);
    }
    facts.language = words().language();
    facts.missingWords = missingWords();
    for (const std::string& key : facts.missingWords)
        log::error("no words for '", key, "' in ", words().language(), " (lessons/.../words.",
                   words().language(), " or common/words/words.", words().language(), ")");

    int exitCode = facts.missingWords.empty() ? 0 : 1;  // a label shown as its key is a failed run
    if (!plan.captureDir.empty()) {
        Doing doing(cat("writing the captures into ", plan.captureDir.string()));
        Status written = writeCaptures(plan.captureDir, record.lastFinalBytes, record.lastTextures,
                                       s.options.captureFloat);
        if (written && !record.lastPicture.empty())
            written = writePng(plan.captureDir / "picture.png", record.lastPicture);
        if (!written) {
            log::error(written.error());
            exitCode = 1;
        } else {
            log::info(capturesWrittenMessage(plan.captureDir, !record.lastFinalBytes.empty(),
                                             !record.lastPicture.empty(), record.lastTextures.size(),
                                             facts.size.empty()));
        }
    }
    if (!plan.reportFile.empty()) {
        Doing doing(cat("writing the report ", plan.reportFile.string()));
        auto report = buildRunReport(facts, record.lastReport, record.lastTextures, record.lastFinal);
        if (record.lastLayout)
            report["layout"] = layoutJson(*record.lastLayout, facts.size, record.textScale);
        report["clock"] = {
            {"seconds", record.clockSeconds}, {"steps", record.clockSteps}, {"paused", record.clockPaused}};
        if (const auto& p = record.lastPictureScale) {
            // The picture's place (its aspect kept) and the size the lesson rendered at within it.
            report["picture"] = {{"place", {p->place.width, p->place.height}},
                                 {"rendered", {p->rendered.width, p->rendered.height}},
                                 {"scale", p->scale},
                                 {"automatic", p->automatic}};
        }
        auto json = dumpJson(report, 2) + "\n";
        if (auto written = writeOutput(plan.reportFile, json); !written) {
            log::error(written.error());
            exitCode = 1;
        } else if (!namesStandardOutput(plan.reportFile)) {
            log::info("report written to ", plan.reportFile.string());
        }
    }
    if (!s.options.graphFile.empty()) {
        if (auto written = writeOutput(s.options.graphFile, toDot(record.lastReport)); !written) {
            log::error(written.error());
            exitCode = 1;
        } else if (!namesStandardOutput(s.options.graphFile)) {
            log::info("frame graph written to ", s.options.graphFile.string(), " (dot -Tpng draws it)");
        }
    }
    if (facts.glErrors > 0)
        log::error(facts.glErrors, " GL error(s) in this run; the last: ", facts.lastGlError);
    return exitCode;
}

}  // namespace fx
