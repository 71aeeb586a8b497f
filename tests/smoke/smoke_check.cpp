// Checks one headless lesson run (its report and captures): no GL error, no NaN or Inf in any
// texture or in the final image, a final image that is not flat, and a final image within the
// stated tolerance of the golden image. Prints every failure; exit code 1 when any.
//
// One opt-in: a step that exists to show a NaN (lesson 05 keeps the chapter's 0/0 at the blur centre)
// names, in its report's facts, the textures that may hold non-finite values:
//   "facts": {"expectNonFiniteIn": "blur.offset, blur.result"}
// Only those textures, and only with the fact present; and at least one of them must really hold a
// NaN or Inf, or the step no longer shows what it is for. The final image is never excused.
//   fx_smoke_check <capture dir> <report.json> <golden.png> <output dir for diffs> [--expect-gl-errors]
//                  [--tolerance RMSE,MAX]
//   fx_smoke_check --report-only <report.json> <WxH>
// --tolerance replaces the golden tolerance (8-bit levels) for another rasteriser than llvmpipe, whose
// goldens these are (tools/gpu/run.sh on a GPU).
// The second form checks only the report (a run resized while it ran): the same GL error and NaN
// checks, and a last frame of WxH; it has no picture to compare. Both fail on a pass that ran without
// declaring its taps (render/pass_traffic.hpp).
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "image/golden.hpp"
#include "image/image_stats.hpp"
#include "image/png_file.hpp"

namespace {

// 8-bit levels. llvmpipe renders the same bytes on every run; the tolerance leaves room for
// another Mesa version rounding an edge differently, not for a changed picture.
constexpr fx::GoldenTolerance kTolerance{1.5, 64};

int failures = 0;
void fail(const std::string& what) {
    std::fprintf(stderr, "FAIL: %s\n", what.c_str());
    ++failures;
}

bool hasNonFinite(const nlohmann::json& stats) {
    for (auto& channel : stats) {
        if (channel.value("nan", 0) > 0 || channel.value("inf", 0) > 0) return true;
    }
    return false;
}

// "a, b" -> {"a", "b"}: the names of the textures a step expects NaN or Inf in.
std::vector<std::string> expectedNonFinite(const nlohmann::json& report) {
    std::vector<std::string> names;
    if (!report.contains("facts") || !report["facts"].is_object()) return names;
    const nlohmann::json& facts = report["facts"];
    if (!facts.contains("expectNonFiniteIn") || !facts["expectNonFiniteIn"].is_string()) return names;
    std::stringstream list(facts["expectNonFiniteIn"].get<std::string>());
    std::string name;
    while (std::getline(list, name, ',')) {
        auto first = name.find_first_not_of(' '), last = name.find_last_not_of(' ');
        if (first != std::string::npos) names.push_back(name.substr(first, last - first + 1));
    }
    return names;
}

// The checks that need only the report; false when it cannot be read at all.
bool checkReport(const std::string& reportPath, bool expectGlErrors, nlohmann::json& report) {
    std::ifstream in(reportPath);
    if (!in) {
        fail("no report at " + reportPath);
        return false;
    }
    report = nlohmann::json::parse(in, nullptr, false);
    if (report.is_discarded()) {
        fail("report is not JSON: " + reportPath);
        return false;
    }
    std::int64_t glErrors = report.value("glErrors", -1);
    if (glErrors != 0)
        fail("GL errors: " + std::to_string(glErrors) + " (" + report.value("lastGlError", "") + ")");
    if (expectGlErrors && report.value("glExpectedErrors", 0) == 0)
        fail("this step exists to show GL errors, but none were counted");
    std::vector<std::string> excused = expectedNonFinite(report);
    bool excusedFound = false;
    for (auto& texture : report["textures"]) {
        if (texture.contains("stats") && hasNonFinite(texture["stats"])) {
            std::string name = texture.value("name", "?");
            if (std::find(excused.begin(), excused.end(), name) != excused.end()) {
                excusedFound = true;
                std::printf("NaN or Inf in texture %s, as this step means to show\n", name.c_str());
            } else {
                fail("NaN or Inf in texture " + name);
            }
        }
    }
    if (!excused.empty() && !excusedFound) {
        fail("this step exists to show NaN or Inf in " + report["facts"].value("expectNonFiniteIn", "") +
             ", but none was found");
    }
    if (hasNonFinite(report["final"]["stats"])) fail("NaN or Inf in the final image");
    for (auto& pass : report["passes"]) {
        if (pass.value("status", "") == "executor failed")
            fail("pass " + pass.value("name", "?") + ": " + pass.value("reason", ""));
        // Every pass that runs says how many texture lookups it makes per pixel (the cost model's taps).
        if (pass.value("executed", false) && (!pass.contains("taps") || pass["taps"].is_null()))
            fail("pass " + pass.value("name", "?") + " declares no taps (Pass::setTaps)");
    }
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    nlohmann::json report;
    if (argc == 4 && std::string(argv[1]) == "--report-only") {
        int width = 0, height = 0;
        if (std::sscanf(argv[3], "%dx%d", &width, &height) != 2) {
            std::fprintf(stderr, "%s: expected a size WxH, got \"%s\"\n", argv[0], argv[3]);
            return 2;
        }
        if (!checkReport(argv[2], false, report)) return 1;
        if (report["final"].value("size", nlohmann::json::array()) != nlohmann::json::array({width, height}))
            fail("the last frame is " + report["final"].value("size", nlohmann::json()).dump() + ", not [" +
                 std::to_string(width) + ", " + std::to_string(height) + "]");
        return failures == 0 ? 0 : 1;
    }
    auto usage = [&] {
        std::fprintf(stderr,
                     "usage: %s CAPTURE_DIR REPORT GOLDEN OUT_DIR [--expect-gl-errors] [--tolerance R,M]\n",
                     argv[0]);
        std::fprintf(stderr, "       %s --report-only REPORT WxH\n", argv[0]);
        return 2;
    };
    if (argc < 5) return usage();
    std::string captureDir = argv[1], reportPath = argv[2], golden = argv[3], outDir = argv[4];
    bool expectGlErrors = false;
    fx::GoldenTolerance tolerance = kTolerance;
    for (int i = 5; i < argc; ++i) {
        const std::string flag = argv[i];
        if (flag == "--expect-gl-errors") {
            expectGlErrors = true;
        } else if (flag == "--tolerance" && i + 1 < argc) {
            char end = 0;
            if (std::sscanf(argv[++i], "%lf,%d%c", &tolerance.maxRmse, &tolerance.maxAbs, &end) != 2 ||
                tolerance.maxRmse < 0 || tolerance.maxAbs < 0) {
                std::fprintf(stderr,
                             "%s: --tolerance: expected RMSE,MAX in 8-bit levels (1.5,64), got \"%s\"\n",
                             argv[0], argv[i]);
                return 2;
            }
        } else {
            return usage();
        }
    }
    if (!checkReport(reportPath, expectGlErrors, report)) return 1;

    auto finalImage = fx::readPng(captureDir + "/final.png");
    if (!finalImage) {
        fail(finalImage.error());
    } else {
        if (fx::isFlat(*finalImage, 2)) fail("the final image is flat (one colour)");
        auto verdict = fx::checkGolden(*finalImage, golden, tolerance, outDir);
        if (!verdict) {
            fail(verdict.error());
        } else if (!verdict->passed()) {
            fail(verdict->message);
        } else {
            std::printf("%s\n", verdict->message.c_str());
        }
    }
    return failures == 0 ? 0 : 1;
}
