#pragma once
// Transient textures, reused within a frame and across frames. A texture is keyed by its spec
// (width, height, format, mip levels): a released one serves the next request with the same key,
// so resources with disjoint lifetimes share one allocation. A texture nobody acquired for
// framesBeforeEviction frames is destroyed, which is how a resize or a step change frees memory.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "render/texture_allocator.hpp"

namespace fx {

struct PoolStats {
    std::uint64_t liveBytes = 0;   // allocated now, in use or waiting for reuse
    std::uint64_t inUseBytes = 0;  // acquired and not yet released
    std::uint64_t peakBytes = 0;   // most live bytes since creation (or resetPeak)
    std::size_t liveTextures = 0;
    std::size_t inUseTextures = 0;
};

class TexturePool {
public:
    inline static constexpr int kDefaultFramesBeforeEviction = 3;

    explicit TexturePool(TextureAllocator& allocator,
                         int framesBeforeEviction = kDefaultFramesBeforeEviction);
    // Destroys every texture, so it must go before the GL context does.
    ~TexturePool();
    TexturePool(const TexturePool&) = delete;
    TexturePool& operator=(const TexturePool&) = delete;

    // A texture with exactly this spec, labelled `label`. Prefers a free texture that already has
    // the label (so a resource keeps the same texture frame after frame), then any free texture with
    // the key, then creates one. Returns 0 if the allocator fails.
    NativeTexture acquire(const TextureSpec& spec, std::string_view label);
    // Hands a texture back for reuse; releasing something the pool did not hand out is logged.
    void release(NativeTexture texture);

    // Call once per frame, after the frame's textures are released: ages free textures and destroys
    // those unused for framesBeforeEviction frames.
    void endFrame();
    // Destroys every free texture now.
    void trim();

    PoolStats stats() const;
    std::uint64_t liveBytes() const { return stats().liveBytes; }
    std::uint64_t inUseBytes() const { return stats().inUseBytes; }
    std::uint64_t peakBytes() const { return peakBytes_; }
    void resetPeak();

    int framesBeforeEviction() const { return framesBeforeEviction_; }
    std::uint64_t frameIndex() const { return frame_; }

private:
    struct Entry {
        TextureSpec spec;
        NativeTexture texture = 0;
        std::string label;
        std::uint64_t bytes = 0;
        std::uint64_t lastUsedFrame = 0;
        bool inUse = false;
    };

    void destroyEntry(std::size_t index);

    TextureAllocator& allocator_;
    int framesBeforeEviction_;
    std::vector<Entry> entries_;
    std::uint64_t frame_ = 0;
    std::uint64_t peakBytes_ = 0;
};

}  // namespace fx
