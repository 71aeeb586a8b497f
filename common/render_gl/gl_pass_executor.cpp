#include "render_gl/gl_pass_executor.hpp"

#include "base/log.hpp"
#include "render/frame_graph.hpp"
#include "render/state_diff.hpp"
#include "render_gl/gl_state.hpp"

namespace fx {

GlPassExecutor::GlPassExecutor(PassTimer& timer, GlExecutorOptions options)
    : timer_(timer), options_(options) {}

void GlPassExecutor::beginFrame(const FrameGraph&) {
    timer_.beginFrame();
}

Result<GLuint> GlPassExecutor::framebufferFor(const Pass& pass, PassContext& ctx) {
    if (pass.writesPresentedOutput()) return options_.presentFramebuffer;
    Attachments key;
    for (TextureHandle h : pass.colorAttachments()) key.colors.push_back(ctx.native(h));
    if (auto depth = pass.depthAttachment()) {
        key.depth = ctx.native(*depth);
        key.depthStencil = hasStencil(ctx.texture(*depth).spec.format);
    }
    if (key.colors.empty() && key.depth == 0) return 0u;  // a compute or storage-only pass
    // Named by its textures' labels, not this pass's names for them: the pool shares a texture between
    // names (render/texture_pool.hpp), and the framebuffer serves every pass that draws into it.
    std::string label;
    for (GLuint color : key.colors)
        label += (label.empty() ? "" : " + ") + gl::objectLabel(GL_TEXTURE, color);
    if (key.depth != 0) label += (label.empty() ? "" : " + ") + gl::objectLabel(GL_TEXTURE, key.depth);
    auto it = framebuffers_.find(key);
    if (it != framebuffers_.end()) it->second.relabel(label);
    if (it == framebuffers_.end()) {
        gl::Framebuffer fbo(label);
        for (std::size_t i = 0; i < key.colors.size(); ++i) {
            glNamedFramebufferTexture(fbo.name(), GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i),
                                      key.colors[i], 0);
        }
        if (key.depth != 0) {
            glNamedFramebufferTexture(fbo.name(),
                                      key.depthStencil ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT,
                                      key.depth, 0);
        }
        fbo.setDrawBuffers(static_cast<int>(key.colors.size()));
        if (auto status = fbo.checkComplete(); !status) return Error{status.error()};
        it = framebuffers_.emplace(key, std::move(fbo)).first;
    }
    return it->second.name();
}

bool GlPassExecutor::beginPass(const Pass& pass, PassContext& ctx) {
    group_.emplace(pass.name());
    auto framebuffer = framebufferFor(pass, ctx);
    if (!framebuffer) {
        failure_ = framebuffer.error();
        log::error("pass '", pass.name(), "' not run: ", failure_);
        group_.reset();
        return false;
    }
    failure_.clear();
    glBindFramebuffer(GL_FRAMEBUFFER, *framebuffer);
    Size2D target = ctx.targetSize();
    if (options_.checkState) {
        // Before the pass's own state goes on: what it would run with for every field it leaves open.
        PassWrites writes{pass.depthAttachment().has_value() || pass.writesPresentedOutput(),
                          !pass.colorAttachments().empty()};
        inherited_ = inheritedDependencies(pass.state(), snapshotGlState(), writes);
    }
    applyGlState(pass.state(), target);

    const PassState& s = pass.state();
    if (s.clearColor) {
        auto colors = pass.writesPresentedOutput() ? std::size_t(1) : pass.colorAttachments().size();
        for (std::size_t i = 0; i < colors; ++i) {
            glClearNamedFramebufferfv(*framebuffer, GL_COLOR, static_cast<GLint>(i), s.clearColor->data());
        }
    }
    if (s.clearDepth) glClearNamedFramebufferfv(*framebuffer, GL_DEPTH, 0, &*s.clearDepth);

    if (options_.checkState) stateAtBegin_ = snapshotGlState();
    timer_.begin(pass.name());
    return true;
}

void GlPassExecutor::endPass(const Pass& pass, PassRecord& record) {
    if (!failure_.empty()) {
        record.reason = failure_;
        return;
    }
    timer_.end(pass.name());
    record.timeMs = timer_.latestMs(pass.name());
    record.timingMethod = std::string(toString(timer_.method()));
    if (options_.checkState) {
        // What the body changed that the pass did not declare: the next pass inherits it.
        for (auto& d : diffState(snapshotGlState(), stateAtBegin_)) record.stateLeft.push_back(d.text());
        record.stateInherited = std::move(inherited_);
        inherited_.clear();
    }
    group_.reset();
}

void GlPassExecutor::endFrame(const FrameGraph&, FrameReport&) {
    group_.reset();
}

}  // namespace fx
