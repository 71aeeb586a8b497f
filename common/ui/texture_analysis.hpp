#pragma once
// What is in one level of a texture: the range the auto-fit uses, the histogram under the view, and
// the numbers of NaN, infinite and negative texels the highlight marks. The inspector counts them on
// the GPU (ui/gpu_texture_stats.hpp: a compute reduction, a few hundred bytes read back); the CPU
// version here (the texture read back exactly, counted with image_stats) is what the GPU's numbers
// are tested against, and what formats the compute pass cannot read (sRGB) use. Either way the
// inspector refreshes it when the selection or level changes and a few times a second at most
// (TextureAnalyser), not every frame.
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "image/image.hpp"
#include "image/image_stats.hpp"
#include "ui/texture_source.hpp"
#include "ui/view_settings.hpp"

namespace fx {

struct ValueHistogram {
    // Bins cover [low, high] in equal steps, or in equal ratios when logarithmic: HDR light, where a
    // sun 30 times brighter than the sky would squeeze everything else into the first bin. On a
    // logarithmic histogram the first bin also holds everything below low (zero included).
    float low = 0.0f, high = 1.0f;
    bool logarithmic = false;
    int channels = 0;
    std::array<std::vector<std::uint32_t>, 4> counts;  // per channel, equal-width bins over [low, high]
    std::uint32_t peak = 0;                            // the fullest bin of any channel

    // Where a value falls along the histogram: 0 at low, 1 at high.
    double fraction(double value) const;
};

struct TextureAnalysis {
    std::string name;
    int level = 0;
    Size2D size{};
    int channels = 0;
    bool linearDepth = false;  // the values below are distances, not stored depth
    // Depth texels at the far plane (stored 1): the sky, not a surface. With linearDepth they are
    // left out of the statistics and the histogram, so auto-fit spreads the range over the surfaces.
    std::int64_t farPlaneTexels = 0;
    // Per channel, of the values as shown (depth linearised): min and max of the finite ones.
    std::vector<ChannelStats> stats;
    // Texels (not values): a texel counts once, as NaN if any channel is NaN, else as infinite if any
    // channel is, else as negative if any channel is below zero. The view colours them the same way.
    std::int64_t nanTexels = 0, infTexels = 0, negativeTexels = 0;
    ValueHistogram histogram;

    // The finite range of the channels that are switched on (all of them if none is).
    bool rangeOf(const std::array<bool, 4>& channels, float& low, float& high) const;
};

// The analysis of an image read back from a texture. With linearDepth, channel 0 holds depth
// values and is turned into distances with the camera's planes before anything is counted.
TextureAnalysis analyseImage(const FloatImage& image, bool linearDepth, float cameraNear, float cameraFar,
                             int bins = 128);

// The histogram's range for these statistics (its counts empty): [min, max] of the finite values of
// every channel, logarithmic from a floor 5 decades below the top when the light has a long bright
// tail. analyseImage and the GPU's statistics (ui/gpu_texture_stats.hpp) both choose it here.
ValueHistogram histogramRange(const std::vector<ChannelStats>& stats, float smallestPositive,
                              bool linearDepth, int channels);

// The same linearisation the view shader does (shaders/ui/view_common.glsl).
float linearizeDepth(float depth, float cameraNear, float cameraFar);

// Keeps the analysis of the texture the inspector shows and refreshes it when what is shown changes,
// or when it is older than `interval` seconds.
class GpuTextureStats;

class TextureAnalyser {
public:
    // forceGpu: count on the GPU even on a software renderer (tests).
    explicit TextureAnalyser(double interval = 0.5, bool forceGpu = false);
    ~TextureAnalyser();
    TextureAnalyser(const TextureAnalyser&) = delete;
    TextureAnalyser& operator=(const TextureAnalyser&) = delete;

    // Returns true when it read the texture back this call.
    bool update(const TextureSource& source, const ViewSettings& settings, double deltaSeconds);
    void invalidate() { valid_ = false; }
    bool valid() const { return valid_; }
    const TextureAnalysis& analysis() const { return analysis_; }
    // Whether it counts on the GPU (a compute reduction) rather than reading the texture back.
    bool countsOnGpu() const;

private:
    double interval_;
    double age_ = 0.0;
    bool valid_ = false;
    float near_ = 0.0f, far_ = 0.0f;
    TextureAnalysis analysis_;
    bool forceGpu_ = false;
    bool softwareChecked_ = false;
    std::unique_ptr<GpuTextureStats> gpu_;  // made on first use, in the GL context, on a GPU
};

// The next texel holding a NaN or an infinity in any channel, in reading order (rows bottom-up, as
// GL stores them) after (afterX, afterY), wrapping round to the start; (-1, -1) starts at the first.
// `count` receives how many such texels the image has. Nothing when it has none.
struct TexelPosition {
    int x = 0, y = 0;
};
std::optional<TexelPosition> nextSpecialTexel(const FloatImage& image, int afterX, int afterY,
                                              std::int64_t* count);

}  // namespace fx
