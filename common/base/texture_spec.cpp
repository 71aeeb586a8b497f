#include "base/texture_spec.hpp"

#include <algorithm>

#include "base/log.hpp"

namespace fx {

Size2D TextureSpec::levelSize(int level) const {
    return {mipLevelSize(width, level), mipLevelSize(height, level)};
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

std::uint64_t textureBytes(const TextureSpec& spec) {
    std::uint64_t texels = 0;
    for (int level = 0; level < spec.mipLevels; ++level) {
        texels += static_cast<std::uint64_t>(mipLevelSize(spec.width, level)) *
                  static_cast<std::uint64_t>(mipLevelSize(spec.height, level));
    }
    return texels * static_cast<std::uint64_t>(bytesPerTexel(spec.format));
}

std::string toString(const TextureSpec& spec) {
    return cat(spec.width, "x", spec.height, " ", toString(spec.format), ", ", spec.mipLevels,
               spec.mipLevels == 1 ? " mip" : " mips");
}

}  // namespace fx
