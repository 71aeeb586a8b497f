#pragma once
// One frame's passes and textures. A lesson declares them every frame; compile() orders them from
// the declarations, checks them and culls what reaches nothing; execute() runs the rest through a
// PassExecutor, taking transient textures from a TexturePool just in time and handing them back
// after their last reader. See docs/frame-graph.md.
//
//   FrameGraph graph({.size = {1280, 720}});
//   auto shadowMap = graph.declareTexture("shadow.map", {TextureSize::absolute(2048, 2048),
//                                                         TextureFormat::Depth32F});
//   auto hdr = graph.declareTexture("scene.color", {TextureSize::output(), TextureFormat::RGBA16F});
//   graph.addPass("scene", drawScene).read(shadowMap).writeColor(hdr);
//   graph.addPass("shadow map", drawShadows).writeDepth(shadowMap);  // runs first all the same
//   graph.addPass("tonemap", tonemap).read(hdr).writeColor(graph.output());
//   graph.execute(pool, executor);
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "base/result.hpp"
#include "render/dead_stack.hpp"
#include "render/frame_report.hpp"
#include "render/graph_compiler.hpp"
#include "render/pass.hpp"
#include "render/pass_context.hpp"
#include "render/pass_executor.hpp"
#include "render/pass_group.hpp"
#include "render/texture_pool.hpp"

namespace fx {

// What the frame presents. native 0 is the window's default framebuffer: it can be drawn into but
// not sampled, and not combined with texture attachments in one pass.
struct OutputTarget {
    Size2D size{};
    std::string name = "output";
    TextureFormat format = TextureFormat::RGBA8;
    NativeTexture native = 0;
};

class FrameGraph {
public:
    explicit FrameGraph(OutputTarget output);
    // Hands retained textures back to the pool if releaseTextures() was not called.
    ~FrameGraph();
    FrameGraph(const FrameGraph&) = delete;
    FrameGraph& operator=(const FrameGraph&) = delete;

    // --- Declaring ---
    // The presented output (always the first texture).
    TextureHandle output() const { return TextureHandle{0}; }
    Size2D outputSize() const { return outputSize_; }
    // A transient texture: allocated from the pool only if a pass that writes it runs.
    TextureHandle declareTexture(std::string name, const TextureDesc& desc);
    // A texture owned elsewhere (history, a cached map). Its content outlives the frame, so a pass
    // that writes it is never culled for "output unused". `sizeRule`: the size it follows, when it
    // follows the output (history at half resolution), for the traffic model (render/pass_traffic.hpp).
    TextureHandle importTexture(std::string name, const TextureSpec& spec, NativeTexture native,
                                std::optional<TextureSize> sizeRule = std::nullopt);
    Pass& addPass(std::string name, Pass::Body body = {});

    // Tells the graph that `requirement` (see Pass::needs) cannot be met this frame, and why; the
    // runner does this for the scene features the scene lacks, before the lesson declares anything.
    void setUnmet(std::string requirement, std::string reason);
    // Why `requirement` cannot be met; nullptr when it can (everything is met unless told otherwise).
    const std::string* unmetReason(std::string_view requirement) const;
    bool meets(std::string_view requirement) const { return unmetReason(requirement) == nullptr; }
    // Passes and textures declared from now on join `group` (nullptr: none), and passes need what
    // it needs; returns the group that was open. PassGroup::Scope calls this.
    const PassGroup* openGroup(const PassGroup* group);

    // Keeps a texture's producers alive and the texture itself held until releaseTextures(), so the
    // overlay can show it. By name, because the overlay chooses before the lesson declares; a name
    // no texture has this frame is listed in the report's unknownTargets.
    void inspect(std::string textureName);
    // The same for a texture the runner reads back (a capture).
    void capture(std::string textureName);
    void capture(TextureHandle texture);

    // --- Compiling and running ---
    // Orders, checks and culls. Errors name the passes and textures involved; all are collected.
    Status compile();
    bool compiled() const { return compiled_; }
    const std::vector<std::string>& errors() const { return report_.errors; }

    // Compiles if needed, then runs what runs. Nothing runs when compile failed, or when the output is
    // 0x0 (every pass is then reported as "frame skipped"). The bodies run now, after the functions
    // that declared them returned, so first the stack those functions used is poisoned: a body that
    // captured one of their locals by reference fails loudly instead of reading a leftover
    // (render/dead_stack.hpp). Inlined, so the poison starts right below the caller's frame.
    [[gnu::always_inline]] Status execute(TexturePool& pool, PassExecutor& executor) {
        poisonDeadStack();
        return executeDeclared(pool, executor);
    }
    // Hands inspected and captured transients back to the pool; call after the overlay and captures
    // are done with them and before TexturePool::endFrame.
    void releaseTextures();

    // --- Facts ---
    bool owns(TextureHandle texture) const { return texture.index < textures_.size(); }
    std::size_t textureCount() const { return textures_.size(); }
    const TextureView& texture(TextureHandle texture) const;
    std::optional<TextureHandle> findTexture(std::string_view name) const;
    std::size_t passCount() const { return passes_.size(); }
    const Pass& pass(std::uint32_t declaredIndex) const { return *passes_.at(declaredIndex); }
    const Pass* findPass(std::string_view name) const;
    // Pass indices. Derived order covers every pass; execution order only those that run.
    const std::vector<std::uint32_t>& derivedOrder() const { return compiledGraph_.derivedOrder; }
    const std::vector<std::uint32_t>& executionOrder() const { return compiledGraph_.executionOrder; }
    // Filled by compile(), completed by execute() and the executor.
    const FrameReport& report() const { return report_; }
    // See PassContext::targetSize.
    Size2D targetSize(const Pass& pass) const;

private:
    Status executeDeclared(TexturePool& pool, PassExecutor& executor);
    void resolveTextures();
    void buildReport();
    // The texture as the traffic model sees it: at kTrafficModelSize where it follows the output.
    TextureSpec modelSpec(const GraphTexture& texture) const;
    PassRecord& recordOf(std::uint32_t pass);
    TextureRecord& recordOf(TextureHandle texture) { return report_.textures[texture.index]; }

    Size2D outputSize_;
    std::vector<GraphTexture> textures_;
    PassList passes_;
    std::vector<std::string> inspectNames_;
    std::vector<std::string> captureNames_;
    std::vector<std::pair<std::string, std::string>> unmet_;  // requirement, reason
    const PassGroup* openGroup_ = nullptr;
    std::vector<std::uint32_t> textureGroups_;  // per texture: the group open when it was declared

    bool compiled_ = false;
    bool compileOk_ = false;
    bool executed_ = false;
    CompiledGraph compiledGraph_;
    FrameReport report_;
    std::vector<std::size_t> reportSlot_;  // per pass: its row in report_.passes
    TexturePool* pool_ = nullptr;          // set by execute, for releaseTextures
    std::vector<std::uint32_t> held_;      // transients acquired and not yet released
};

}  // namespace fx
