#pragma once
// The seam between the frame graph's logic and the GPU. FrameGraph::execute calls these around each
// pass that runs, in execution order; the GL layer implements them (framebuffer, state, debug group,
// timer). Every hook has an empty default, so a test executor overrides only what it checks.
namespace fx {

class FrameGraph;
class Pass;
class PassContext;
struct PassRecord;
struct FrameReport;

class PassExecutor {
public:
    virtual ~PassExecutor() = default;

    virtual void beginFrame(const FrameGraph& /*graph*/) {}
    // Before the body: textures the pass writes first are already acquired (ctx.texture gives them).
    // The place to open a debug group named pass.name(), bind the framebuffer built from
    // pass.colorAttachments() / pass.depthAttachment() (or the window's framebuffer when the output's
    // native handle is 0), apply pass.state() with ctx.targetSize() as the default viewport, clear,
    // and start a timer.
    // Returns false when the pass cannot run (an incomplete framebuffer): its body is skipped, the
    // pass is reported as not executed, and endPass still runs so the executor can say why.
    virtual bool beginPass(const Pass& /*pass*/, PassContext& /*ctx*/) { return true; }
    // After the body: stop the timer, close the debug group, and fill record.timeMs, timingMethod and,
    // in debug builds, stateLeft.
    virtual void endPass(const Pass& /*pass*/, PassRecord& /*record*/) {}
    // After the last pass, before any retained texture goes back to the pool.
    virtual void endFrame(const FrameGraph& /*graph*/, FrameReport& /*report*/) {}
};

}  // namespace fx
