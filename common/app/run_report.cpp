#include "app/run_report.hpp"

#include <cmath>

namespace fx {

nlohmann::ordered_json statsJson(const std::vector<ChannelStats>& stats) {
    auto channels = nlohmann::ordered_json::array();
    for (const ChannelStats& s : stats) {
        channels.push_back({{"min", s.min},
                            {"max", s.max},
                            {"mean", s.mean},
                            {"nan", s.nanCount},
                            {"inf", s.infCount},
                            {"negative", s.negativeCount}});
    }
    return channels;
}

namespace {

nlohmann::ordered_json usesJson(const std::vector<TextureUseRecord>& uses) {
    auto out = nlohmann::ordered_json::array();
    for (auto& u : uses) out.push_back(u.texture);
    return out;
}

}  // namespace

void RunFacts::addFrame(double cpuMs, double passMs) {
    frameCpuMs.push_back(cpuMs);
    frameGpuMs.push_back(passMs);
    if (frameCpuMs.size() > kKeptFrames) frameCpuMs.pop_front();
    if (frameGpuMs.size() > kKeptFrames) frameGpuMs.pop_front();
    ++framesRun;
}

nlohmann::ordered_json buildRunReport(const RunFacts& f, const FrameReport& frame,
                                      const std::vector<CapturedTexture>& textures,
                                      const FloatImage& finalImage) {
    nlohmann::ordered_json j;
    j["lesson"] = f.lesson;
    j["scene"] = f.scene;
    j["step"] = f.step;
    j["stepTitle"] = f.stepTitle;
    j["size"] = {f.size.width, f.size.height};
    j["context"] = f.contextKind;
    j["renderer"] = f.renderer;
    j["glVersion"] = f.glVersion;
    j["glErrors"] = f.glErrors;
    j["glExpectedErrors"] = f.glExpectedErrors;
    j["glExpectedErrorsThisStep"] = f.glExpectedErrorsThisStep;
    j["glWarnings"] = f.glWarnings;
    if (!f.lastGlError.empty()) j["lastGlError"] = f.lastGlError;
    j["timing"] = {{"method", f.timingMethod}, {"reason", f.timingReason}};
    auto frames = nlohmann::ordered_json::array();
    const std::uint64_t first = f.framesRun - f.frameCpuMs.size();  // the frames kept are the last ones
    for (std::size_t i = 0; i < f.frameCpuMs.size(); ++i) {
        frames.push_back({{"index", first + i},
                          {"cpuMs", f.frameCpuMs[i]},
                          {"passMs", i < f.frameGpuMs.size() ? f.frameGpuMs[i] : 0.0}});
    }
    j["frames"] = frames;

    auto passes = nlohmann::ordered_json::array();
    for (const PassRecord& p : frame.passes) {
        nlohmann::ordered_json pj;
        pj["name"] = p.name;
        pj["executed"] = p.executed;
        pj["status"] = std::string(toString(p.status));
        pj["reason"] = p.reason;
        pj["timeMs"] = p.timeMs ? nlohmann::ordered_json(*p.timeMs) : nlohmann::ordered_json(nullptr);
        pj["timingMethod"] = p.timingMethod;
        pj["reads"] = usesJson(p.reads);
        pj["writes"] = usesJson(p.writes);
        // The cost model at 1920x1080 (render/pass_traffic.hpp); taps null: not declared.
        pj["taps"] = p.taps ? nlohmann::ordered_json(*p.taps) : nlohmann::ordered_json(nullptr);
        pj["trafficBytes1080p"] = {{"read", p.traffic.readBytes}, {"written", p.traffic.writtenBytes}};
        pj["stateLeft"] = p.stateLeft;
        pj["stateInherited"] = p.stateInherited;
        passes.push_back(pj);
    }
    j["passes"] = passes;
    const PassTraffic traffic = frame.modelledTraffic();
    j["modelledTraffic1080p"] = {{"readBytes", traffic.readBytes},
                                 {"writtenBytes", traffic.writtenBytes},
                                 {"totalBytes", traffic.total()},
                                 {"tapsPerPixel", frame.tapsPerOutputPixel()},
                                 {"passesWithoutTaps", frame.undeclaredTaps()}};
    j["declaredOrder"] = frame.declaredOrder;
    j["derivedOrder"] = frame.derivedOrder;
    if (!frame.errors.empty()) j["graphErrors"] = frame.errors;

    auto texturesJson = nlohmann::ordered_json::array();
    for (const TextureRecord& t : frame.textures) {
        nlohmann::ordered_json tj;
        tj["name"] = t.name;
        tj["size"] = {t.spec.width, t.spec.height};
        tj["format"] = std::string(toString(t.spec.format));
        tj["mips"] = t.spec.mipLevels;
        tj["bytes"] = t.bytes;
        tj["producer"] = t.producer;
        tj["allocated"] = t.allocated;
        if (!t.reason.empty()) tj["reason"] = t.reason;
        for (const CapturedTexture& c : textures) {
            if (c.name == t.name) tj["stats"] = statsJson(c.stats);
        }
        texturesJson.push_back(tj);
    }
    j["textures"] = texturesJson;
    j["pool"] = {{"liveBytes", frame.pool.liveBytes},
                 {"peakBytes", frame.pool.peakBytes},
                 {"liveTextures", frame.pool.liveTextures}};
    j["final"] = {{"size", {finalImage.width, finalImage.height}},
                  {"stats", statsJson(computeStats(finalImage))}};
    j["shaderErrors"] = f.shaderErrors;
    nlohmann::ordered_json facts = nlohmann::ordered_json::object();
    // "true" and "false" become JSON booleans: the smoke script looks for "expectErrorsInStep": true.
    for (auto& [k, v] : f.lessonFacts) {
        if (v == "true" || v == "false")
            facts[k] = (v == "true");
        else
            facts[k] = v;
    }
    j["facts"] = facts;
    // The facts the overlay's panel shows, in its order and words (the handout lists them per step).
    auto shown = nlohmann::ordered_json::array();
    for (auto& [label, value] : f.shownFacts) shown.push_back({{"label", label}, {"value", value}});
    j["shownFacts"] = shown;
    nlohmann::ordered_json params = nlohmann::ordered_json::array();
    for (const ParamFact& p : f.params) {
        nlohmann::ordered_json param = {
            {"name", p.name}, {"label", p.label}, {"value", p.value}, {"source", p.source}};
        if (!p.changedInSteps.empty()) {
            nlohmann::ordered_json steps = nlohmann::ordered_json::object();
            for (const auto& [step, value] : p.changedInSteps) steps[std::to_string(step)] = value;
            param["changedInSteps"] = steps;
        }
        if (p.pinned) param["pinned"] = true;
        params.push_back(param);
    }
    j["params"] = params;
    j["language"] = f.language;
    j["missingWords"] = f.missingWords;
    return j;
}

}  // namespace fx
