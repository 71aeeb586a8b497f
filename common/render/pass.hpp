#pragma once
// One pass of a frame: its name, the textures it reads and writes, the GL state it depends on, and
// the body that draws. Lessons get a Pass from FrameGraph::addPass and declare on it:
//
//   graph.addPass("shadow map", drawShadows).writeDepth(shadowMap).setState({.depthTest = true});
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "render/graph_texture.hpp"
#include "render/pass_state.hpp"

namespace fx {

class FrameGraph;
class PassContext;
class PassGroup;

// Why a pass the lesson declared may be off before the graph even looks at its outputs.
enum class PassSwitch {
    On,
    Disabled,      // the lesson's current step leaves it out ("disabled in step 2")
    NotCalledFor,  // the scene has nothing for it ("scene has no particle emitter")
};

class Pass {
public:
    using Body = std::function<void(PassContext&)>;

    // --- Declarations (each returns the pass, so they chain) ---
    // Sampled read: the pass runs after every pass that writes the texture. A pass must not sample a
    // texture it renders into (a feedback loop, undefined in GL): the graph refuses it.
    Pass& read(TextureHandle texture);
    // Sampled read of another mip level than the one this pass renders into: a mip chain kept in one
    // texture, level k sampled while level k+1 is attached. The one case where a pass may sample a
    // texture it also writes; the pass body must make sure it samples only that level.
    Pass& readOtherLevel(TextureHandle texture);
    // Write without reading: this pass creates (or clears) the texture and runs before its other users.
    Pass& write(TextureHandle texture, TextureUsage usage);
    Pass& writeColor(TextureHandle texture) { return write(texture, TextureUsage::ColorAttachment); }
    Pass& writeDepth(TextureHandle texture) { return write(texture, TextureUsage::DepthAttachment); }
    Pass& writeStorage(TextureHandle texture) { return write(texture, TextureUsage::Storage); }
    // Read and write (additive accumulation): runs after the creator, in declaration order with
    // other modifiers, before pure readers.
    Pass& modify(TextureHandle texture, TextureUsage usage);
    // Declares a transient texture and writes it, for a texture that belongs to this pass.
    TextureHandle create(std::string textureName, const TextureDesc& desc, TextureUsage usage);

    Pass& setState(const PassState& state);
    PassState& state() { return state_; }

    // The pass is declared but does not run, whatever reads its outputs; the reason is shown as is.
    Pass& disable(std::string reason);
    Pass& notCalledFor(std::string reason);
    // Something outside the graph the pass exists for (a scene feature, named by the layer that knows
    // it). When the graph was told this frame cannot meet it (FrameGraph::setUnmet), the pass is not
    // called for, with the graph's reason, whatever the lesson's step says.
    Pass& needs(std::string requirement);
    // Joins `group` (and needs what it needs), as if declared inside a PassGroup::Scope.
    Pass& joinGroup(const PassGroup& group);
    // Runs even when nothing the graph knows reads its outputs (it has effects the graph cannot see).
    Pass& keepAlive();
    // Any number the lesson or executor wants back in the report (a step, an effect id).
    Pass& setTag(std::int64_t tag);
    // Texture lookups per pixel it writes (texture(), texelFetch(), imageLoad): a 13-tap downsample
    // declares 13; a pass that draws geometry counts per covered pixel. The report and the pass table
    // show them beside the modelled memory traffic (render/pass_traffic.hpp).
    Pass& setTaps(double perOutputPixel);

    // --- Facts ---
    const std::string& name() const { return name_; }
    std::uint32_t declaredIndex() const { return index_; }
    std::int64_t tag() const { return tag_; }
    // Absent until setTaps: the report then says the pass did not declare them.
    std::optional<double> taps() const { return taps_; }
    // The PassGroup open on the graph when the pass was added; 0: none.
    std::uint32_t group() const { return group_; }
    const PassState& state() const { return state_; }
    const Body& body() const { return body_; }
    // One entry per texture, in the order first declared.
    const std::vector<TextureAccess>& accesses() const { return accesses_; }
    // Colour attachments in declaration order: the first is GL_COLOR_ATTACHMENT0, and so on.
    std::vector<TextureHandle> colorAttachments() const;
    std::optional<TextureHandle> depthAttachment() const;
    std::vector<TextureHandle> storageWrites() const;
    std::vector<TextureHandle> sampledReads() const;
    // True when the pass writes the graph's presented output (handle FrameGraph::output()).
    bool writesPresentedOutput() const;
    bool keptAlive() const { return keepAlive_; }
    PassSwitch switchState() const { return switch_; }
    const std::string& switchReason() const { return switchReason_; }
    // Mistakes found while declaring (unknown handle, two usages), reported by FrameGraph::compile.
    const std::vector<std::string>& declarationErrors() const { return declarationErrors_; }

private:
    friend class FrameGraph;
    Pass(FrameGraph& graph, std::uint32_t index, std::string name, Body body);
    // The pass's access to `texture` after this one is merged in; nullptr when it was refused.
    TextureAccess* addAccess(TextureHandle texture, bool reads, bool writes, TextureUsage usage);

    FrameGraph& graph_;
    std::uint32_t index_;
    std::string name_;
    Body body_;
    PassState state_;
    std::vector<TextureAccess> accesses_;
    std::int64_t tag_ = 0;
    std::optional<double> taps_;
    std::uint32_t group_ = 0;
    bool keepAlive_ = false;
    PassSwitch switch_ = PassSwitch::On;
    std::string switchReason_;
    std::vector<std::string> declarationErrors_;
};

}  // namespace fx
