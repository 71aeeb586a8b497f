#pragma once
// Golden images: a reviewed picture in the source tree that a rendered image must stay close to.
//
// checkGolden(actual, golden, tolerance, outputFolder)
//   - FXLAB_UPDATE_GOLDEN=1 in the environment: writes `actual` as the new golden file and passes
//     with a note (look at the picture before committing it).
//   - golden file missing: fails, saying how to create it.
//   - shapes differ, or RMSE / max difference above the tolerance: fails, and writes
//     <outputFolder>/<golden stem>.actual.png and (same shape only) <golden stem>.diff.png so a
//     person can see what changed. The output folder is the build's, never the source tree.
//   - otherwise passes; the message gives the measured numbers either way.
// Both images are compared as RGBA (the golden file is read that way; `actual` is widened like the
// display widens it), with differences in 8-bit levels.
// A Result error means the check could not be made (an unreadable golden file, a write that failed).
#include <filesystem>
#include <optional>
#include <string>

#include "base/result.hpp"
#include "image/image.hpp"
#include "image/image_compare.hpp"

namespace fx {

struct GoldenTolerance {
    double maxRmse = 0.0;  // in 8-bit levels (0..255)
    int maxAbs = 0;        // the largest single channel difference allowed, in 8-bit levels
};

enum class GoldenOutcome { Match, Mismatch, Missing, Updated };

struct GoldenVerdict {
    GoldenOutcome outcome = GoldenOutcome::Missing;
    std::string message;                         // one paragraph for the test log
    std::optional<ImageDifference> difference;   // when both images could be compared
    std::filesystem::path actualPath, diffPath;  // the pictures written on a mismatch

    bool passed() const { return outcome == GoldenOutcome::Match || outcome == GoldenOutcome::Updated; }
};

// The environment variable that turns a golden check into an update: FXLAB_UPDATE_GOLDEN=1.
inline constexpr const char* kUpdateGoldenVariable = "FXLAB_UPDATE_GOLDEN";
bool goldenUpdateRequested();

Result<GoldenVerdict> checkGolden(const ByteImage& actual, const std::filesystem::path& goldenPng,
                                  const GoldenTolerance& tolerance,
                                  const std::filesystem::path& outputFolder);

}  // namespace fx
