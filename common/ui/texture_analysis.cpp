#include "ui/texture_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "gl/readback.hpp"
#include "render_gl/pass_timer.hpp"
#include "ui/gpu_texture_stats.hpp"

namespace fx {

float linearizeDepth(float depth, float cameraNear, float cameraFar) {
    float z = depth * 2.0f - 1.0f;
    return 2.0f * cameraNear * cameraFar /
           std::max(cameraFar + cameraNear - z * (cameraFar - cameraNear), 1e-30f);
}

double ValueHistogram::fraction(double value) const {
    if (logarithmic) {
        if (!(value > low)) return 0.0;
        return std::log(value / low) / std::log(double(high) / low);
    }
    return high > low ? (value - low) / (double(high) - low) : 0.0;
}

bool TextureAnalysis::rangeOf(const std::array<bool, 4>& on, float& low, float& high) const {
    bool any = false;
    bool noneOn = true;
    for (int c = 0; c < channels && c < 4; ++c) noneOn = noneOn && !on[std::size_t(c)];
    for (int c = 0; c < channels && c < int(stats.size()); ++c) {
        if (!noneOn && !on[std::size_t(c)]) continue;
        const ChannelStats& s = stats[std::size_t(c)];
        if (s.finiteCount == 0) continue;
        low = any ? std::min(low, s.min) : s.min;
        high = any ? std::max(high, s.max) : s.max;
        any = true;
    }
    return any;
}

ValueHistogram histogramRange(const std::vector<ChannelStats>& stats, float smallestPositive,
                              bool linearDepth, int channels) {
    ValueHistogram h;
    h.channels = channels;
    bool any = false;
    double sum = 0.0;
    std::int64_t count = 0;
    for (const ChannelStats& s : stats) {
        if (s.finiteCount == 0) continue;
        h.low = any ? std::min(h.low, s.min) : s.min;
        h.high = any ? std::max(h.high, s.max) : s.max;
        sum += s.mean * double(s.finiteCount);
        count += s.finiteCount;
        any = true;
    }
    if (!any) {
        h.low = 0.0f;
        h.high = 1.0f;
    }
    // Light with a long bright tail: bins in equal ratios, from a floor 5 decades below the top.
    const double mean = count > 0 ? sum / double(count) : 0.0;
    if (!linearDepth && h.low >= 0.0f && h.high > 1.0f && mean > 0.0 && h.high > 16.0 * mean &&
        std::isfinite(smallestPositive)) {
        h.logarithmic = true;
        h.low = std::max(smallestPositive, h.high * 1e-5f);
    }
    return h;
}

TextureAnalysis analyseImage(const FloatImage& image, bool linearDepth, float cameraNear, float cameraFar,
                             int bins) {
    TextureAnalysis a;
    a.size = {image.width, image.height};
    a.channels = image.channels;
    a.linearDepth = linearDepth;
    if (image.empty()) return a;

    const std::size_t texels = image.texelCount();
    const auto channels = static_cast<std::size_t>(image.channels);
    for (std::size_t t = 0; t < texels; ++t) {
        bool nan = false, inf = false, negative = false;
        for (std::size_t c = 0; c < channels; ++c) {
            float v = image.texels[t * channels + c];
            nan = nan || std::isnan(v);
            inf = inf || std::isinf(v);
            negative = negative || (v < 0.0f && !std::isinf(v));
        }
        if (nan) {
            ++a.nanTexels;
        } else if (inf) {
            ++a.infTexels;
        } else if (negative) {
            ++a.negativeTexels;
        }
    }

    // The values as the view shows them.
    const FloatImage* shown = &image;
    FloatImage distances;
    if (linearDepth) {
        distances = image;
        for (std::size_t t = 0; t < texels; ++t) {
            float& d = distances.texels[t * channels];
            if (d >= 1.0f) {
                // The sky: counted apart; +Inf keeps it out of the finite range and the bins.
                ++a.farPlaneTexels;
                d = std::numeric_limits<float>::infinity();
            } else if (std::isfinite(d)) {
                d = linearizeDepth(d, cameraNear, cameraFar);
            }
        }
        shown = &distances;
    }
    a.stats = computeStats(*shown);

    float smallestPositive = std::numeric_limits<float>::infinity();
    for (float v : shown->texels) {
        if (v > 0.0f && std::isfinite(v)) smallestPositive = std::min(smallestPositive, v);
    }
    a.histogram = histogramRange(a.stats, smallestPositive, linearDepth, image.channels);
    ValueHistogram& h = a.histogram;
    bins = std::max(bins, 1);
    for (std::size_t c = 0; c < channels && c < 4; ++c) h.counts[c].assign(std::size_t(bins), 0);
    for (std::size_t t = 0; t < texels; ++t) {
        for (std::size_t c = 0; c < channels && c < 4; ++c) {
            float v = shown->texels[t * channels + c];
            if (!std::isfinite(v)) continue;
            int bin = static_cast<int>(h.fraction(v) * bins);
            std::uint32_t& n = h.counts[c][std::size_t(std::clamp(bin, 0, bins - 1))];
            h.peak = std::max(h.peak, ++n);
        }
    }
    return a;
}

TextureAnalyser::TextureAnalyser(double interval, bool forceGpu) : interval_(interval), forceGpu_(forceGpu) {}
TextureAnalyser::~TextureAnalyser() = default;

bool TextureAnalyser::countsOnGpu() const {
    return gpu_ && gpu_->usable();
}

bool TextureAnalyser::update(const TextureSource& source, const ViewSettings& settings, double deltaSeconds) {
    if (!source.alive()) return false;
    age_ += std::max(deltaSeconds, 0.0);
    const int level = std::clamp(settings.level, 0, source.levels() - 1);
    const bool linear = showsLinearDepth(settings, source.spec);
    const bool same = valid_ && analysis_.name == source.name && analysis_.level == level &&
                      analysis_.linearDepth == linear &&
                      (!linear || (near_ == settings.cameraNear && far_ == settings.cameraFar));
    if (same && age_ < interval_) return false;
    // On a GPU the compute reduction reads back a few hundred bytes instead of the whole level. A
    // software renderer runs "the GPU" on the CPU, where the compute pass measured 2.5 times slower
    // than reading the texture back and counting it directly (docs/bench.md): there it reads back.
    if (!gpu_ && !softwareChecked_) {
        softwareChecked_ = true;
        const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
        if (!isSoftwareRenderer(renderer ? renderer : "") || forceGpu_)
            gpu_ = std::make_unique<GpuTextureStats>(GpuTextureStats::create());
    }
    std::optional<TextureAnalysis> counted;
    if (gpu_)
        counted =
            gpu_->analyse(source.native, source.spec, level, linear, settings.cameraNear, settings.cameraFar);
    analysis_ = counted ? std::move(*counted)
                        : analyseImage(gl::readTexture(source.native, source.spec, level), linear,
                                       settings.cameraNear, settings.cameraFar);
    analysis_.name = source.name;
    analysis_.level = level;
    near_ = settings.cameraNear;
    far_ = settings.cameraFar;
    valid_ = true;
    age_ = 0.0;
    return true;
}

std::optional<TexelPosition> nextSpecialTexel(const FloatImage& image, int afterX, int afterY,
                                              std::int64_t* count) {
    if (count) *count = 0;
    if (image.empty()) return std::nullopt;
    auto special = [&](std::size_t texel) {
        for (int c = 0; c < image.channels; ++c) {
            if (!std::isfinite(image.texels[texel * std::size_t(image.channels) + std::size_t(c)]))
                return true;
        }
        return false;
    };
    const std::size_t n = image.texelCount();
    // Where the search starts: just after the given texel (or at the first one).
    std::size_t start = 0;
    if (afterX >= 0 && afterY >= 0 && afterX < image.width && afterY < image.height)
        start = (std::size_t(afterY) * std::size_t(image.width) + std::size_t(afterX) + 1) % n;
    std::optional<std::size_t> found;
    for (std::size_t i = 0; i < n; ++i) {
        if (!special(i)) continue;
        if (count) ++*count;
        // The first at or after the start wins; before it, only the first one (for the wrap round).
        if (i >= start && (!found || *found < start)) found = i;
        if (!found) found = i;
    }
    if (!found) return std::nullopt;
    return TexelPosition{int(*found % std::size_t(image.width)), int(*found / std::size_t(image.width))};
}

}  // namespace fx
