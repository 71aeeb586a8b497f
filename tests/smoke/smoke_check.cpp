// Checks one headless lesson run (its report and captures): no GL error, no NaN or Inf in any
// texture or in the final image, a final image that is not flat, and a final image within the
// stated tolerance of the golden image. Prints every failure; exit code 1 when any.
//   fx_smoke_check <capture dir> <report.json> <golden.png> <output dir for diffs> [--expect-gl-errors]
#include <cstdio>
#include <fstream>
#include <string>

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

}  // namespace

int main(int argc, char** argv) {
    if (argc < 5) {
        std::fprintf(stderr, "usage: %s CAPTURE_DIR REPORT GOLDEN OUT_DIR [--expect-gl-errors]\n", argv[0]);
        return 2;
    }
    std::string captureDir = argv[1], reportPath = argv[2], golden = argv[3], outDir = argv[4];
    bool expectGlErrors = argc > 5 && std::string(argv[5]) == "--expect-gl-errors";

    std::ifstream in(reportPath);
    if (!in) {
        fail("no report at " + reportPath);
        return 1;
    }
    nlohmann::json report = nlohmann::json::parse(in, nullptr, false);
    if (report.is_discarded()) {
        fail("report is not JSON: " + reportPath);
        return 1;
    }
    std::int64_t glErrors = report.value("glErrors", -1);
    if (glErrors != 0) fail("GL errors: " + std::to_string(glErrors) + " (" + report.value("lastGlError", "") + ")");
    if (expectGlErrors && report.value("glExpectedErrors", 0) == 0) fail("this step exists to show GL errors, but none were counted");
    for (auto& texture : report["textures"]) {
        if (texture.contains("stats") && hasNonFinite(texture["stats"])) {
            fail("NaN or Inf in texture " + texture.value("name", "?"));
        }
    }
    if (hasNonFinite(report["final"]["stats"])) fail("NaN or Inf in the final image");
    for (auto& pass : report["passes"]) {
        if (pass.value("status", "") == "executor failed") fail("pass " + pass.value("name", "?") + ": " + pass.value("reason", ""));
    }

    auto finalImage = fx::readPng(captureDir + "/final.png");
    if (!finalImage) {
        fail(finalImage.error());
    } else {
        if (fx::isFlat(*finalImage, 2)) fail("the final image is flat (one colour)");
        auto verdict = fx::checkGolden(*finalImage, golden, kTolerance, outDir);
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
