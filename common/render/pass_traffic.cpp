#include "render/pass_traffic.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

namespace fx {

PassTraffic& PassTraffic::operator+=(const PassTraffic& other) {
    readBytes += other.readBytes;
    writtenBytes += other.writtenBytes;
    return *this;
}

std::uint64_t levelZeroBytes(const TextureSpec& spec) {
    return static_cast<std::uint64_t>(std::max(spec.width, 0)) *
           static_cast<std::uint64_t>(std::max(spec.height, 0)) *
           static_cast<std::uint64_t>(bytesPerTexel(spec.format));
}

PassTraffic modelTraffic(const ModelledAccess* accesses, std::size_t count) {
    PassTraffic t;
    for (std::size_t i = 0; i < count; ++i) {
        const ModelledAccess& a = accesses[i];
        const std::uint64_t bytes = levelZeroBytes(a.spec);
        if (a.reads) t.readBytes += bytes;
        if (!a.writes) continue;
        t.writtenBytes += bytes;
        t.pixels = std::max(t.pixels, static_cast<std::uint64_t>(std::max(a.spec.width, 0)) *
                                          static_cast<std::uint64_t>(std::max(a.spec.height, 0)));
    }
    return t;
}

double tapsPerOutputPixel(double taps, const PassTraffic& traffic, Size2D output) {
    const double pixels = double(std::max(output.width, 0)) * double(std::max(output.height, 0));
    return pixels > 0.0 ? taps * double(traffic.pixels) / pixels : 0.0;
}

std::string megabytesText(std::uint64_t bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f MB", double(bytes) / 1e6);
    return text;
}

}  // namespace fx
