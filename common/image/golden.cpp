#include "image/golden.hpp"

#include <cstdlib>
#include <cstring>
#include <system_error>

#include "base/log.hpp"
#include "image/png_file.hpp"

namespace fx {
namespace fs = std::filesystem;

bool goldenUpdateRequested() {
    const char* value = std::getenv(kUpdateGoldenVariable);
    return value != nullptr && std::strcmp(value, "1") == 0;
}

namespace {

std::string describeDifference(const ImageDifference& d) {
    return cat("RMSE ", d.rmse, ", max difference ", d.maxAbs, ", ", d.differingTexels, " texels differ");
}

std::string describeTolerance(const GoldenTolerance& t) {
    return cat("tolerance: RMSE <= ", t.maxRmse, ", max difference <= ", t.maxAbs);
}

Result<GoldenVerdict> update(const ByteImage& actual, const fs::path& goldenPng) {
    if (Status written = writePng(goldenPng, actual); !written) return Error{written.error()};
    GoldenVerdict verdict;
    verdict.outcome = GoldenOutcome::Updated;
    verdict.message = cat("golden image updated: ", goldenPng.string(), " (", kUpdateGoldenVariable,
                          "=1). Look at the picture before committing it.");
    log::warning(verdict.message);
    return verdict;
}

// Writes the pictures a person needs to judge a mismatch; a diff only when the shapes agree.
Status writeEvidence(GoldenVerdict& verdict, const ByteImage& actual, const ByteImage& golden,
                     const fs::path& goldenPng, const fs::path& outputFolder) {
    const std::string stem = goldenPng.stem().string();
    verdict.actualPath = outputFolder / (stem + ".actual.png");
    if (Status written = writePng(verdict.actualPath, actual); !written) return written;
    if (actual.width == golden.width && actual.height == golden.height) {
        auto diff = differenceImage(golden, actual);
        if (!diff) return Error{diff.error()};
        verdict.diffPath = outputFolder / (stem + ".diff.png");
        if (Status written = writePng(verdict.diffPath, *diff); !written) return written;
    }
    return Status::success();
}

}  // namespace

Result<GoldenVerdict> checkGolden(const ByteImage& actual, const fs::path& goldenPng,
                                  const GoldenTolerance& tolerance, const fs::path& outputFolder) {
    if (Status shape = checkShape(actual, "rendered image"); !shape) return Error{shape.error()};
    if (goldenUpdateRequested()) return update(actual, goldenPng);

    std::error_code ec;
    if (!fs::exists(goldenPng, ec)) {
        GoldenVerdict verdict;
        verdict.outcome = GoldenOutcome::Missing;
        verdict.message =
            cat("golden image missing: ", goldenPng.string(), ". To create it, run this test again with ",
                kUpdateGoldenVariable, "=1, then look at the picture before committing it.");
        return verdict;
    }
    auto golden = readPng(goldenPng);
    if (!golden) return Error{cat("cannot read the golden image: ", golden.error())};

    const ByteImage rgba = toRgba(actual);
    GoldenVerdict verdict;
    if (rgba.width != golden->width || rgba.height != golden->height) {
        verdict.outcome = GoldenOutcome::Mismatch;
        verdict.message = cat("golden image ", goldenPng.string(), " is ", describeShape(*golden),
                              " but the rendered image is ", describeShape(rgba));
    } else {
        auto difference = compare(*golden, rgba);
        if (!difference) return Error{difference.error()};
        verdict.difference = *difference;
        const bool within = difference->rmse <= tolerance.maxRmse && difference->maxAbs <= tolerance.maxAbs;
        verdict.outcome = within ? GoldenOutcome::Match : GoldenOutcome::Mismatch;
        verdict.message = cat(within ? "matches" : "differs from", " golden image ", goldenPng.string(), ": ",
                              describeDifference(*difference), " (", describeTolerance(tolerance), ")");
    }
    if (verdict.outcome == GoldenOutcome::Mismatch) {
        if (Status written = writeEvidence(verdict, rgba, *golden, goldenPng, outputFolder); !written)
            return Error{cat(verdict.message, "; and the pictures could not be written: ", written.error())};
        verdict.message += cat(". See ", verdict.actualPath.string());
        if (!verdict.diffPath.empty()) verdict.message += cat(" and ", verdict.diffPath.string());
        verdict.message += cat(". If the change is intended, run with ", kUpdateGoldenVariable, "=1.");
    }
    return verdict;
}

}  // namespace fx
