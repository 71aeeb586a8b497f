#pragma once
// Per-pass time. On a GPU: GL_TIMESTAMP queries around each pass, kept in flight for a few frames
// and read only once available, so timing never stalls the pipeline. On a software renderer timer
// queries do not measure rasterisation (llvmpipe read 0.09 ms for a pass that took 23 ms), so the
// timer falls back to fenced wall-clock time: glFinish before and after the pass. --timing
// overrides the choice; the report and the overlay say which method produced the numbers.
#include <chrono>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "base/timing_mode.hpp"
#include "gl/object.hpp"

namespace fx {

enum class TimingMethod { GpuTimestamps, FencedWallClock, Off };

std::string_view toString(TimingMethod method);  // "GL_TIMESTAMP queries", "glFinish + wall clock", "off"

// True for renderers whose timer queries do not cover rasterisation (llvmpipe, softpipe, SwiftShader).
bool isSoftwareRenderer(std::string_view glRenderer);

class PassTimer {
public:
    PassTimer(TimingMode requested, std::string_view glRenderer);

    TimingMethod method() const { return method_; }
    // Why this method: "auto: llvmpipe is a software renderer", "--timing fenced".
    const std::string& reason() const { return reason_; }

    // Collects finished GPU queries (never waits for one).
    void beginFrame();
    void begin(const std::string& pass);
    void end(const std::string& pass);
    // The latest finished measurement of this pass (GPU results lag a few frames behind).
    std::optional<double> latestMs(const std::string& pass) const;

private:
    struct InFlight {
        std::string pass;
        gl::QueryName start, stop;
    };
    TimingMethod method_;
    std::string reason_;
    std::map<std::string, double> latest_;
    std::vector<InFlight> inFlight_;
    std::vector<gl::QueryName> spareQueries_;
    std::optional<InFlight> open_;
    std::chrono::steady_clock::time_point wallStart_;

    gl::QueryName takeQuery();
};

}  // namespace fx
