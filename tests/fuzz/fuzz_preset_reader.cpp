// The preset reader (ParamSet::fromJson) on any bytes, with a parameter of every type: a refusal that
// changes nothing, or values inside their ranges.
#include <cstdlib>

#include "base/params.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    float length = 0.25f;
    int samples = 8;
    bool on = false;
    int mode = 0;
    fx::ParamSet params;
    params.addFloat("length", &length, 0.0f, 0.5f, "a float");
    params.addInt("samples", &samples, 1, 64, "an integer");
    params.addBool("enabled", &on, "a switch");
    params.addChoice("mode", &mode, {"none", "grayscale", "sepia"}, "a choice");
    fx::Status loaded = params.fromJson(fuzz::text(data, size), "fuzz.preset.json");
    // What the reader promises: a refusal leaves every value as it was; an accepted preset keeps each
    // value in its range.
    const bool asBefore = length == 0.25f && samples == 8 && !on && mode == 0;
    const bool inRange =
        length >= 0.0f && length <= 0.5f && samples >= 1 && samples <= 64 && mode >= 0 && mode <= 2;
    if ((!loaded && !asBefore) || !inRange) std::abort();
    return 0;
}
