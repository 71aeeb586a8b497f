#pragma once
// Transient textures, reused within a frame and across frames. A texture is keyed by its spec
// (width, height, format, mip levels): a released one serves the next request with the same key,
// so resources with disjoint lifetimes share one allocation. A texture nobody acquired for
// framesBeforeEviction frames is destroyed, which is how a resize or a step change frees memory.
//
// A debugger keeps one name per texture (RenderDoc shows the last label), so a shared texture's label
// is every name it holds in a frame, in the order they were acquired ("bloom.down[0] | bloom.flicker"):
// true for every pass that reads or writes it. A name joins the label when it is first acquired; at
// the frame's end the label becomes that frame's names, so a frame like the one before relabels
// nothing, and a debugger's captured frame sees one name from its start to its end.
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

    // A texture with exactly this spec whose label holds `label`. Prefers a free texture whose label
    // already holds it (so a resource keeps the same texture frame after frame), then any free texture
    // with the key, then creates one. Returns 0 if the allocator fails.
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

    // " | " between the names of one texture's label.
    inline static constexpr std::string_view kNameSeparator = " | ";
    // The label of a texture that holds these names, in order.
    static std::string labelFor(const std::vector<std::string>& names);

    int framesBeforeEviction() const { return framesBeforeEviction_; }
    std::uint64_t frameIndex() const { return frame_; }

private:
    struct Entry {
        TextureSpec spec;
        NativeTexture texture = 0;
        std::vector<std::string> labelNames;  // what its label says now
        std::vector<std::string> frameNames;  // the names acquired this frame, in order
        std::uint64_t bytes = 0;
        std::uint64_t lastUsedFrame = 0;
        bool inUse = false;
    };

    void destroyEntry(std::size_t index);
    // Adds `name` to the label when it is not there yet.
    void holdName(Entry& entry, std::string_view name);

    TextureAllocator& allocator_;
    int framesBeforeEviction_;
    std::vector<Entry> entries_;
    std::uint64_t frame_ = 0;
    std::uint64_t peakBytes_ = 0;
};

}  // namespace fx
