#pragma once
// One frame of a lesson on the GPU: build the lesson's graph, execute it through the GL executor,
// read back what was asked for. The interactive loop, captures and the bench sweep all render
// through this one path, so a benchmarked frame is exactly a shown frame.
#include <functional>
#include <string>
#include <vector>

#include "app/capture.hpp"
#include "app/lesson.hpp"
#include "base/timing_mode.hpp"
#include "effects/scene/scene_work.hpp"
#include "platform/context.hpp"
#include "render_gl/gl_pass_executor.hpp"
#include "render_gl/gl_texture_allocator.hpp"

namespace fx {

struct FrameRequest {
    std::vector<std::string> inspect;    // keep these textures (and their producers) alive
    bool readTextures = false;           // read back every texture of the frame (captures, report)
    std::vector<std::string> readNamed;  // read back only these (the bench's effect output)
    bool readFinal = false;              // read back the presented image (after whileHeld drew on it)
    // Where the lesson's output goes: 0 for the context's present framebuffer, else a framebuffer of
    // the frame's size (ui/picture_view.hpp: the picture's own target, shown beside the panels).
    GLuint target = 0;
};

struct RenderedFrame {
    FrameReport report;
    std::vector<CapturedTexture> textures;
    ByteImage finalImage;  // the context's whole framebuffer, overlay and all
    double passMs = 0;     // sum of the pass times the timer had
};

class FrameRenderer {
public:
    FrameRenderer(Context& context, TimingMode timing, bool checkState = true);

    using WhileHeld = std::function<void(const FrameGraph&, const FrameReport&)>;
    // `whileHeld` runs after execution, while inspected textures are still held (the overlay).
    RenderedFrame render(Lesson& lesson, const FrameInfo& frame, const FrameRequest& request,
                         const WhileHeld& whileHeld = {});

    // The scene's features: what it lacks is told to every frame's graph before the lesson declares,
    // so passes that need it are not called for, with the scene's reason (Pass::needs).
    // The same SceneWork runs the lesson's simulations (FrameLoop, before Lesson::update).
    void setSceneWork(SceneWork* work) { work_ = work; }
    SceneWork* sceneWork() const { return work_; }
    // The scene and its meshes every frame draws (the runner's): world() is them at `seconds`.
    void setScene(const Scene& scene, const SceneMeshes& meshes) {
        scene_ = &scene;
        meshes_ = &meshes;
    }
    World world(double seconds) const { return scene_ ? World(*scene_, *meshes_, seconds) : World(); }

    PassTimer& timer() { return timer_; }
    TexturePool& pool() { return pool_; }

private:
    Context& context_;
    GlTextureAllocator allocator_;
    TexturePool pool_;
    PassTimer timer_;
    GlPassExecutor executor_;
    std::uint64_t destroyedSeen_ = 0;
    SceneWork* work_ = nullptr;
    const Scene* scene_ = nullptr;
    const SceneMeshes* meshes_ = nullptr;
};

}  // namespace fx
