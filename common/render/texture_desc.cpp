#include "render/texture_desc.hpp"

#include <algorithm>
#include <cstdint>

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

TextureSpec resolve(const TextureDesc& desc, Size2D outputSize) {
    Size2D size = desc.size.resolve(outputSize);
    int full = fullMipChainLength(size.width, size.height);
    int levels = desc.mipLevels <= kFullMipChain ? full : std::min(desc.mipLevels, full);
    return {size.width, size.height, desc.format, levels};
}

std::string toString(const TextureSize& size) {
    if (!size.relativeToOutput()) return cat(size.first(), "x", size.second());
    if (size.first() == size.second()) return "output";
    return cat(size.first(), "/", size.second(), " output");
}

}  // namespace fx
