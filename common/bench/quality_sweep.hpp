#pragma once
// One measured setting of a quality knob: what the bench writes and the overlay's cost panel draws
// (time against error, the reference marked).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace fx {

// One pass's share of a measured setting: its median time and that time in full-screen copies, and
// what the cost model gives it (render/pass_traffic.hpp): memory traffic at 1920x1080 and its taps.
struct PassCost {
    std::string pass;
    double medianMs = 0;
    double copies = 0;
    std::uint64_t trafficBytes = 0;
    std::optional<double> taps;
};

struct SweepPoint {
    std::string knob;        // parameter name
    std::string value;       // the setting, as --param takes it
    bool reference = false;  // the setting the error is measured against
    bool current = false;    // the setting in use when the sweep started
    double medianMs = 0;     // whole frame (passes), median over the measured frames
    // The frame in full-screen copies: each measured frame is divided by a copy timed just before it
    // (copy, setting, copy, setting...), so a machine that slows down slows both; the median of those
    // ratios (minMultiple and maxMultiple below give their spread).
    double copyMultiple = 0;
    double rmse = 0, psnr = 0, maxAbs = 0;  // final image against the reference setting's, in [0, 1] units
    // The same for the lesson's effect texture (exact floats), when the lesson names one.
    bool hasEffectError = false;
    double effectRmse = 0, effectPsnr = 0, effectMaxAbs = 0;
    // The smallest and largest of the per-frame ratios: the spread a reader should allow for.
    double minMultiple = 0, maxMultiple = 0;
    double copyMs = 0;               // the median of the copies interleaved with this setting
    std::vector<PassCost> passes{};  // every timed pass, in execution order
    // The frame's modelled memory traffic at 1920x1080 and its taps per output pixel: the same on every
    // machine (render/pass_traffic.hpp), the cost axis of `--cost traffic`.
    std::uint64_t trafficBytes = 0;
    double tapsPerPixel = 0;
};

struct SweepResult {
    std::string lesson;
    int width = 0, height = 0;
    std::string timingMethod;
    double copyMs = 0;          // one plain full-screen copy: the median over every row's copies
    int frames = 0;             // measured frames (and interleaved copies) per setting
    std::string effectTexture;  // the texture of the effect* columns, if any
    std::vector<SweepPoint> points;
};

// What a plot's cost axis is (--cost): the measured time in full-screen copies (milliseconds when no
// copy was timed), or the modelled memory traffic at 1920x1080 (render/pass_traffic.hpp), which reads
// the same on every machine.
enum class BenchCost { time, traffic };

// Where a sweep is: rows measured so far (the reference image counts as one) of how many, and what
// the next one is.
struct SweepProgress {
    int done = 0, total = 0;
    std::string next;           // "levels = 4", empty when done
    int frame = 0, frames = 0;  // of the row under way: frames rendered, of how many (0 of 0: none)
    // The share of the whole sweep done, rows and the row under way's frames.
    double fraction() const {
        if (total <= 0) return 0.0;
        return (done + (frames > 0 ? double(frame) / frames : 0.0)) / total;
    }
};

// A sweep measured a slice at a time (one frame of a row), so an app can draw its own frames (and a
// progress bar) between slices and stop early: dropping it mid-way puts the parameters back
// (app/bench.hpp: KnobSweep).
class SweepRun {
public:
    virtual ~SweepRun() = default;
    virtual bool done() const = 0;
    virtual void next() = 0;  // measures one slice (a row is done after several)
    virtual SweepProgress progress() const = 0;
    virtual const SweepResult& result() const = 0;
};

}  // namespace fx
