#pragma once
// Runs the frame graph's passes on GL: for each pass a debug group with its name, the framebuffer
// built from its attachments (checked for completeness, never drawn into when incomplete), its
// declared state and clears, a timer around it, and two state checks: before, the state it depends
// on but did not declare, with the value it inherited (the chapter's shadow pass running with depth
// testing off); afterwards, what its body changed behind the graph's back.
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include "gl/debug_output.hpp"
#include "gl/framebuffer.hpp"
#include "render/pass_executor.hpp"
#include "render/pass_state.hpp"
#include "render_gl/gl_texture_allocator.hpp"
#include "render_gl/pass_timer.hpp"

namespace fx {

struct GlExecutorOptions {
    GLuint presentFramebuffer = 0;  // where passes that write the presented output draw
    bool checkState = true;         // snapshot GL state after each pass (cheap glGets)
};

class GlPassExecutor final : public PassExecutor {
public:
    GlPassExecutor(PassTimer& timer, GlExecutorOptions options);

    void setPresentFramebuffer(GLuint framebuffer) { options_.presentFramebuffer = framebuffer; }

    void beginFrame(const FrameGraph& graph) override;
    bool beginPass(const Pass& pass, PassContext& ctx) override;
    void endPass(const Pass& pass, PassRecord& record) override;
    void endFrame(const FrameGraph& graph, FrameReport& report) override;

    // Framebuffers refer to textures by name; when the pool destroys textures GL may reuse a name,
    // so cached framebuffers are dropped.
    void forgetFramebuffers() { framebuffers_.clear(); }

private:
    struct Attachments {
        std::vector<GLuint> colors;
        GLuint depth = 0;
        bool depthStencil = false;
        auto operator<=>(const Attachments&) const = default;
    };

    PassTimer& timer_;
    GlExecutorOptions options_;
    std::map<Attachments, gl::Framebuffer> framebuffers_;
    std::optional<gl::DebugGroup> group_;
    GlStateSnapshot stateAtBegin_;
    std::vector<std::string> inherited_;  // inheritedDependencies() of the running pass
    std::string failure_;

    // The framebuffer for a pass's attachments, or an error naming it.
    Result<GLuint> framebufferFor(const Pass& pass, PassContext& ctx);
};

}  // namespace fx
