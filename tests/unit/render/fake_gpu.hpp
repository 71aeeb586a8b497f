#pragma once
// Test doubles for the render layer's two seams: an allocator that records every call, and an
// executor that records what ran and which textures each pass saw.
#include <algorithm>
#include <string>
#include <vector>

#include "render/frame_graph.hpp"
#include "render/texture_allocator.hpp"

namespace fx::test {

struct FakeAllocator : TextureAllocator {
    struct Created {
        NativeTexture texture;
        TextureSpec spec;
        std::string label;
    };
    std::vector<Created> created;
    std::vector<NativeTexture> destroyed;
    std::vector<std::pair<NativeTexture, std::string>> relabelled;
    NativeTexture next = 1;

    NativeTexture create(const TextureSpec& spec, std::string_view label) override {
        created.push_back({next, spec, std::string(label)});
        return next++;
    }
    void destroy(NativeTexture texture) override { destroyed.push_back(texture); }
    void relabel(NativeTexture texture, std::string_view label) override {
        relabelled.emplace_back(texture, std::string(label));
    }
};

struct RecordingExecutor : PassExecutor {
    std::vector<std::string> begun;
    std::vector<std::string> ended;
    // Live bytes of the pool at each beginPass, to see when textures come and go.
    const TexturePool* pool = nullptr;
    std::vector<std::uint64_t> inUseAtBegin;
    bool frameBegun = false;
    bool frameEnded = false;

    void beginFrame(const FrameGraph&) override { frameBegun = true; }
    // Passes whose beginPass fails, as an incomplete framebuffer would.
    std::vector<std::string> refuse;

    bool beginPass(const Pass& pass, PassContext&) override {
        begun.push_back(pass.name());
        if (pool != nullptr) inUseAtBegin.push_back(pool->inUseBytes());
        return std::find(refuse.begin(), refuse.end(), pass.name()) == refuse.end();
    }
    void endPass(const Pass& pass, PassRecord& record) override {
        ended.push_back(pass.name());
        record.timeMs = 0.25;
        record.timingMethod = "fake clock";
    }
    void endFrame(const FrameGraph&, FrameReport&) override { frameEnded = true; }
};

inline std::vector<std::string> names(const FrameGraph& graph, const std::vector<std::uint32_t>& order) {
    std::vector<std::string> out;
    for (std::uint32_t p : order) out.push_back(graph.pass(p).name());
    return out;
}

inline bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

}  // namespace fx::test
