#include "render/frame_report.hpp"

#include <algorithm>

#include "base/log.hpp"

namespace fx {

double FrameReport::timedMs() const {
    double total = 0;
    for (const PassRecord& p : passes) total += p.timeMs.value_or(0.0);
    return total;
}

PassTraffic FrameReport::modelledTraffic() const {
    PassTraffic total;
    for (const PassRecord& p : passes) {
        if (p.status == PassStatus::Runs) total += p.traffic;
    }
    return total;
}

double FrameReport::tapsPerOutputPixel() const {
    double taps = 0;
    for (const PassRecord& p : passes) {
        if (p.status == PassStatus::Runs && p.taps) taps += fx::tapsPerOutputPixel(*p.taps, p.traffic);
    }
    return taps;
}

std::vector<std::string> FrameReport::undeclaredTaps() const {
    std::vector<std::string> names;
    for (const PassRecord& p : passes) {
        if (p.status == PassStatus::Runs && !p.taps) names.push_back(p.name);
    }
    return names;
}

std::vector<std::string> FrameReport::executedPasses() const {
    std::vector<std::string> names;
    for (const PassRecord& p : passes) {
        if (p.executed) names.push_back(p.name);
    }
    return names;
}

std::string joinedNames(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& n : names) text += (text.empty() ? "" : ", ") + n;
    return text;
}

const PassRecord* FrameReport::findPass(std::string_view name) const {
    auto it = std::find_if(passes.begin(), passes.end(), [&](const PassRecord& p) { return p.name == name; });
    return it == passes.end() ? nullptr : &*it;
}

const TextureRecord* FrameReport::findTexture(std::string_view name) const {
    auto it = std::find_if(textures.begin(), textures.end(),
                           [&](const TextureRecord& t) { return t.name == name; });
    return it == textures.end() ? nullptr : &*it;
}

std::string_view toString(PassStatus status) {
    switch (status) {
        case PassStatus::Runs:
            return "runs";
        case PassStatus::OutputUnused:
            return "output unused";
        case PassStatus::Disabled:
            return "disabled";
        case PassStatus::NotCalledFor:
            return "not called for";
        case PassStatus::MissingInput:
            return "missing input";
        case PassStatus::FrameSkipped:
            return "frame skipped";
        case PassStatus::ExecutorFailed:
            return "executor failed";
    }
    return "?";
}

std::string describe(const FrameReport& report) {
    std::string out = cat("frame at ", toString(report.outputSize), "\n");
    for (const auto& e : report.errors) out += cat("  error: ", e, "\n");
    for (const auto& p : report.passes) {
        out += cat("  ", p.executed ? "ran    " : "skipped", " ", p.name);
        if (p.timeMs) out += cat(" (", *p.timeMs, " ms, ", p.timingMethod, ")");
        if (p.status == PassStatus::Runs) {
            out += cat(" [", megabytesText(p.traffic.total()), " at 1080p",
                       p.taps ? cat(", ", *p.taps, " taps") : std::string(), "]");
        }
        if (!p.reason.empty()) out += cat(": ", p.reason);
        out += "\n";
    }
    for (const auto& t : report.textures) {
        out +=
            cat("  texture ", t.name, " ", toString(t.spec), ", ", t.bytes, " bytes, ", toString(t.origin));
        if (!t.producer.empty()) out += cat(", from '", t.producer, "'");
        if (t.origin == TextureOrigin::Transient)
            out += t.allocated ? ", allocated" : cat(", not allocated: ", t.reason);
        out += "\n";
    }
    out += cat("  modelled traffic at 1080p: ", megabytesText(report.modelledTraffic().total()), ", ",
               report.tapsPerOutputPixel(), " taps per output pixel\n");
    out += cat("  pool: ", report.pool.liveBytes, " bytes live, ", report.pool.inUseBytes, " in use, ",
               report.pool.peakBytes, " peak\n");
    return out;
}

}  // namespace fx
