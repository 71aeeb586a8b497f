#include "app/frame_renderer.hpp"

#include <algorithm>

#include "base/log.hpp"
#include "gl/readback.hpp"

namespace fx {

FrameRenderer::FrameRenderer(Context& context, TimingMode timing, bool checkState)
    : context_(context),
      pool_(allocator_),
      timer_(timing, context.renderer()),
      executor_(timer_, {context.presentFramebuffer(), checkState}) {}

RenderedFrame FrameRenderer::render(Lesson& lesson, const FrameInfo& frame, const FrameRequest& request,
                                    const WhileHeld& whileHeld) {
    RenderedFrame out;
    executor_.setPresentFramebuffer(request.target ? request.target : context_.presentFramebuffer());
    FrameGraph graph(OutputTarget{frame.size, "output", TextureFormat::RGBA8, 0});
    if (work_) work_->describeTo(graph);
    lesson.buildFrame(graph, frame);
    for (auto& name : request.inspect) graph.inspect(name);
    if (request.readTextures) {
        for (std::uint32_t t = 1; t < graph.textureCount(); ++t) graph.capture(TextureHandle{t});
    }
    for (auto& name : request.readNamed) graph.capture(name);
    if (auto status = graph.execute(pool_, executor_); !status) log::error("frame graph: ", status.error());
    out.report = graph.report();
    for (auto& p : out.report.passes) out.passMs += p.timeMs.value_or(0.0);

    if (request.readTextures || !request.readNamed.empty()) {
        out.textures = readFrameTextures(graph);
        if (!request.readTextures) {
            std::erase_if(out.textures, [&](const CapturedTexture& t) {
                return std::find(request.readNamed.begin(), request.readNamed.end(), t.name) ==
                       request.readNamed.end();
            });
        }
    }
    if (whileHeld) whileHeld(graph, out.report);
    if (request.readFinal) {
        // What is on the screen: the whole window (the picture's place and the panels beside it).
        const Size2D shown = request.target ? context_.framebufferSize() : frame.size;
        out.finalImage = gl::readFramebufferRgba8(context_.presentFramebuffer(), shown.width, shown.height);
    }
    // Inspected and captured textures go back to the pool only now.
    graph.releaseTextures();
    pool_.endFrame();
    // Evicted textures free their names for reuse: framebuffers that refer to them must go too.
    if (allocator_.destroyedCount() != destroyedSeen_) {
        destroyedSeen_ = allocator_.destroyedCount();
        executor_.forgetFramebuffers();
    }
    return out;
}

}  // namespace fx
