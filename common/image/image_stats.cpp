#include "image/image_stats.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace fx {

std::vector<ChannelStats> computeStats(const FloatImage& image) {
    const int channels = std::max(image.channels, 0);
    std::vector<ChannelStats> stats(static_cast<std::size_t>(channels));
    std::vector<double> sums(stats.size(), 0.0);
    for (auto& s : stats) {
        s.min = std::numeric_limits<float>::infinity();
        s.max = -std::numeric_limits<float>::infinity();
    }
    const std::size_t count = image.texelCount();
    for (std::size_t i = 0; i < count; ++i) {
        for (int c = 0; c < channels; ++c) {
            const float v =
                image.texels[i * static_cast<std::size_t>(channels) + static_cast<std::size_t>(c)];
            ChannelStats& s = stats[static_cast<std::size_t>(c)];
            if (std::isnan(v)) {
                ++s.nanCount;
            } else if (std::isinf(v)) {
                ++s.infCount;
            } else {
                ++s.finiteCount;
                if (v < 0.0f) ++s.negativeCount;
                s.min = std::min(s.min, v);
                s.max = std::max(s.max, v);
                sums[static_cast<std::size_t>(c)] += v;
            }
        }
    }
    for (std::size_t c = 0; c < stats.size(); ++c) {
        ChannelStats& s = stats[c];
        if (s.finiteCount == 0) {
            s.min = s.max = 0.0f;
            continue;
        }
        s.mean = sums[c] / static_cast<double>(s.finiteCount);
    }
    return stats;
}

bool isFlat(const ByteImage& image, int tolerance) {
    const std::size_t channels = static_cast<std::size_t>(std::max(image.channels, 0));
    if (image.empty() || image.texels.size() < channels) return true;
    for (std::size_t i = channels; i < image.texels.size(); ++i) {
        const int difference = std::abs(int(image.texels[i]) - int(image.texels[i % channels]));
        if (difference > tolerance) return false;
    }
    return true;
}

}  // namespace fx
