#include "render/texture_desc.hpp"

#include <algorithm>

#include "base/log.hpp"

namespace fx {
namespace {

int scaleAxis(int outputAxis, int numerator, int denominator) {
    if (outputAxis <= 0 || numerator <= 0 || denominator <= 0) return 0;
    auto scaled = static_cast<std::int64_t>(outputAxis) * numerator / denominator;
    return static_cast<int>(std::clamp<std::int64_t>(scaled, 1, INT32_MAX));
}

}  // namespace

Size2D TextureSize::resolve(Size2D outputSize) const {
    if (!relative_) return {std::max(a_, 0), std::max(b_, 0)};
    return {scaleAxis(outputSize.width, a_, b_), scaleAxis(outputSize.height, a_, b_)};
}

int fullMipChainLength(int width, int height) {
    int largest = std::max({width, height, 1});
    int levels = 1;
    while (largest > 1) {
        largest >>= 1;
        ++levels;
    }
    return levels;
}

int mipLevelSize(int size, int level) {
    if (size <= 0) return 0;
    if (level >= 31) return 1;
    return std::max(1, size >> std::max(level, 0));
}

TextureSpec resolve(const TextureDesc& desc, Size2D outputSize) {
    Size2D size = desc.size.resolve(outputSize);
    int full = fullMipChainLength(size.width, size.height);
    int levels = desc.mipLevels <= kFullMipChain ? full : std::min(desc.mipLevels, full);
    return {size.width, size.height, desc.format, levels};
}

std::uint64_t textureBytes(const TextureSpec& spec) {
    std::uint64_t texels = 0;
    for (int level = 0; level < spec.mipLevels; ++level) {
        texels += static_cast<std::uint64_t>(mipLevelSize(spec.width, level)) *
                  static_cast<std::uint64_t>(mipLevelSize(spec.height, level));
    }
    return texels * static_cast<std::uint64_t>(bytesPerTexel(spec.format));
}

std::string toString(Size2D size) {
    return cat(size.width, "x", size.height);
}

std::string toString(const TextureSize& size) {
    if (!size.relativeToOutput()) return cat(size.first(), "x", size.second());
    if (size.first() == size.second()) return "output";
    return cat(size.first(), "/", size.second(), " output");
}

std::string toString(const TextureSpec& spec) {
    return cat(spec.width, "x", spec.height, " ", toString(spec.format), ", ", spec.mipLevels,
               spec.mipLevels == 1 ? " mip" : " mips");
}

}  // namespace fx
