#pragma once
// The inspector's statistics of one texture level counted on the GPU (shaders/ui/texture_stats.comp):
// a compute pass reduces the texture to per-channel min, max, sum and counts, and a second one bins
// the histogram, so what comes back is about 2 KB however large the texture is, instead of the whole
// texture as floats (a 1920x1080 RGBA16F level is 33 MB read back and converted on the CPU).
//
// The numbers are those of analyseImage (ui/texture_analysis.hpp), which the tests compare them with:
// counts exactly, min and max exactly, the mean to float precision (the GPU adds in float, the CPU in
// double), and histogram bins exactly except a value that falls on a bin edge, which float and
// double rounding may put in neighbouring bins.
//
//   GpuTextureStats stats = GpuTextureStats::create();
//   std::optional<TextureAnalysis> a = stats.analyse(texture, spec, 0, false, 0.1f, 100.0f);
#include <optional>

#include "base/texture_spec.hpp"
#include "gl/object.hpp"
#include "gl/program.hpp"
#include "ui/texture_analysis.hpp"

namespace fx {

class GpuTextureStats {
public:
    GpuTextureStats() = default;  // empty: no GL
    static GpuTextureStats create();

    bool usable() const { return program_.usable(); }
    // Whether the compute pass reads this format as the CPU path reads it back (sRGB is decoded by
    // texelFetch but not by a read-back, and multisampled textures are not sampler2D).
    static bool handles(const TextureSpec& spec);

    // Nothing when the program did not build or the format is not handled: the caller reads back.
    std::optional<TextureAnalysis> analyse(GLuint texture, const TextureSpec& spec, int level,
                                           bool linearDepth, float cameraNear, float cameraFar,
                                           int bins = 128) const;

private:
    gl::ReloadableProgram program_;
    gl::BufferName totals_, partials_, histogram_;
    gl::SamplerName sampler_;
};

}  // namespace fx
