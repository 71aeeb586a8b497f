#pragma once
// One measured setting of a quality knob: what the bench writes and the overlay's cost panel draws
// (time against error, the reference marked).
#include <string>
#include <vector>

namespace fx {

struct SweepPoint {
    std::string knob;                       // parameter name
    std::string value;                      // the setting, as --param takes it
    bool reference = false;                 // the setting the error is measured against
    bool current = false;                   // the setting in use when the sweep started
    double medianMs = 0;                    // whole frame (passes), median over the measured frames
    double copyMultiple = 0;                // medianMs divided by one full-screen copy at the same size
    double rmse = 0, psnr = 0, maxAbs = 0;  // final image against the reference setting's, in [0, 1] units
    // The same for the lesson's effect texture (exact floats), when the lesson names one.
    bool hasEffectError = false;
    double effectRmse = 0, effectPsnr = 0, effectMaxAbs = 0;
};

struct SweepResult {
    std::string lesson;
    int width = 0, height = 0;
    std::string timingMethod;
    double copyMs = 0;          // one plain full-screen copy, measured in the same run
    std::string effectTexture;  // the texture of the effect* columns, if any
    std::vector<SweepPoint> points;
};

}  // namespace fx
