#pragma once
// What happened in one frame, for the overlay's pass table and inspector and for the run report:
// every pass (those that ran first, in execution order, then the rest) with the reason it did not
// run, and every texture with its size, cost and producer. The executor fills the timing slots.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "render/graph_texture.hpp"
#include "render/pass_traffic.hpp"
#include "render/texture_pool.hpp"

namespace fx {

enum class PassStatus {
    Runs,            // compiled to run (executed says whether it did)
    OutputUnused,    // nothing it writes reaches the output, a capture or an inspected view
    Disabled,        // switched off by the lesson's step
    NotCalledFor,    // switched off because the scene has nothing for it
    MissingInput,    // needs a texture whose producer does not run
    FrameSkipped,    // nothing runs this frame: the output is 0x0, or the graph has errors
    ExecutorFailed,  // compiled to run, but the executor's beginPass refused it (its reason follows)
};

struct TextureUseRecord {
    std::string texture;
    TextureSpec spec{};
    TextureUsage usage = TextureUsage::Sampled;
    bool alsoRead = false;  // a write that also reads (modify)
};

struct PassRecord {
    std::string name;
    std::uint32_t declaredIndex = 0;
    std::int64_t tag = 0;
    std::uint32_t group = 0;  // PassGroup::id() of the group it was declared in; 0: none
    PassStatus status = PassStatus::Runs;
    bool executed = false;
    std::string reason;                    // empty when it runs
    std::vector<TextureUseRecord> reads;   // sampled reads
    std::vector<TextureUseRecord> writes;  // writes, including modifies
    // The cost model (render/pass_traffic.hpp): texture lookups per pixel written, as the pass declared
    // them (none: not declared), and the memory traffic at kTrafficModelSize.
    std::optional<double> taps;
    PassTraffic traffic;
    // Filled by the executor: time of this pass (possibly a few frames old, from a query ring) and
    // how it was measured ("GL_TIME_ELAPSED", "glFinish wall clock").
    std::optional<double> timeMs;
    std::string timingMethod;
    // Filled by a debug executor: the state this pass left that differs from the defaults.
    std::vector<std::string> stateLeft;
    // Filled by a debug executor: state the pass depends on but did not declare, with the value it
    // inherited from the pass before it ("depth test: off (inherited)"). See inheritedDependencies.
    std::vector<std::string> stateInherited;
};

struct TextureRecord {
    std::string name;
    TextureSpec spec{};
    TextureOrigin origin = TextureOrigin::Transient;
    std::uint64_t bytes = 0;  // all mip levels
    std::string producer;     // the pass that creates it; empty for imports nobody writes
    bool allocated = false;   // a transient that got a texture this frame
    std::string reason;       // why it was not allocated (the producer's reason), empty otherwise
    bool inspected = false;
    bool captured = false;
    std::uint32_t group = 0;  // PassGroup::id() of the group it was declared in; 0: none
};

struct FrameReport {
    Size2D outputSize{};
    std::vector<std::string> declaredOrder;   // pass names as the lesson declared them
    std::vector<std::string> derivedOrder;    // all passes in the order the graph derived
    std::vector<PassRecord> passes;           // those that run in execution order, then the others
    std::vector<TextureRecord> textures;      // in declaration order
    std::vector<std::string> errors;          // compile errors; nothing runs when there are any
    std::vector<std::string> unknownTargets;  // inspected or captured names no texture has this frame
    PoolStats pool{};                         // after execution, before retained textures go back

    const PassRecord* findPass(std::string_view name) const;
    // The summed time of every timed pass.
    double timedMs() const;
    // The modelled memory traffic of the passes that run (compiled to run), at kTrafficModelSize.
    PassTraffic modelledTraffic() const;
    // Their taps per output pixel (each pass's taps weighted by its share of the output's pixels);
    // passes that declared none count 0, and undeclaredTaps() lists them.
    double tapsPerOutputPixel() const;
    std::vector<std::string> undeclaredTaps() const;
    // The names of the passes that ran, in the order they ran (what a lesson compares with a chapter's).
    std::vector<std::string> executedPasses() const;
    const TextureRecord* findTexture(std::string_view name) const;
};

std::string_view toString(PassStatus status);
// "a, b, c": a list of names in one line, for facts and reports.
std::string joinedNames(const std::vector<std::string>& names);
// A plain-text table of the report, for logs and the headless run report.
std::string describe(const FrameReport& report);

}  // namespace fx
