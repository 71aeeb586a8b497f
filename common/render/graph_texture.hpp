#pragma once
// How passes refer to the frame's textures and how they use them.
#include <cstdint>
#include <string>
#include <string_view>

#include "render/texture_allocator.hpp"
#include "render/texture_desc.hpp"

namespace fx {

// A texture declared in one frame's graph. Cheap to copy; meaningless in another frame's graph.
struct TextureHandle {
    static constexpr std::uint32_t kInvalid = UINT32_MAX;
    std::uint32_t index = kInvalid;
    bool valid() const { return index != kInvalid; }
    bool operator==(const TextureHandle&) const = default;
};

enum class TextureOrigin {
    Transient,        // declared by the graph, taken from the pool for part of the frame
    Imported,         // owned elsewhere (history, cached maps); never allocated or freed by the graph
    PresentedOutput,  // what the frame presents: the window's framebuffer or the headless target
};

// How a pass touches a texture. Reads are sampled; writes go through an attachment or an image.
enum class TextureUsage { Sampled, ColorAttachment, DepthAttachment, Storage };

// One texture in one pass. A pass that both reads and writes a texture (additive accumulation,
// read-modify-write in a compute pass) has reads and writes set; usage is then how it writes.
struct TextureAccess {
    TextureHandle texture{};
    bool reads = false;
    bool writes = false;
    TextureUsage usage = TextureUsage::Sampled;
    // The pass samples it (Pass::read), as opposed to reading it only through blending or image
    // loads (Pass::modify). Sampled and attached in one pass is a feedback loop the graph refuses...
    bool sampled = false;
    // ... unless the pass samples another mip level than the one it renders into (Pass::readOtherLevel).
    bool otherLevel = false;

    bool creates() const { return writes && !reads; }  // writes without reading: creates or clears it
    bool modifies() const { return writes && reads; }
    bool onlyReads() const { return reads && !writes; }
};

// A texture as a pass body and the executor see it. native is valid from the texture's first pass
// to its last reader (transients), for the whole frame (imported), and 0 for the window's default
// framebuffer.
struct TextureView {
    std::string name;
    TextureSpec spec{};
    NativeTexture native = 0;
    TextureOrigin origin = TextureOrigin::Transient;

    Size2D size() const { return {spec.width, spec.height}; }
};

std::string_view toString(TextureUsage usage);    // "colour attachment"
std::string_view toString(TextureOrigin origin);  // "transient"

}  // namespace fx
