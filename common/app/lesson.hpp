#pragma once
// What a lesson is: who it is, its steps (following the chapter), its parameters, and how it builds
// the frame graph for the current step. Everything else (context, loop, overlay, capture, report)
// is the runner's; a lesson's .cpp ends with FX_LESSON(MyLesson, "Title", "scenes/NN_name.json")
// (app/runner.hpp), which is its main().
//
// The runner owns the lesson's GL lifetime: the lesson object is destroyed while the context is
// still current, on every way out of the run, so GL objects held in members (RAII) need no
// shutdown code. Every gl::ReloadableProgram the lesson or its effects build joins the run's
// gl::ProgramRegistry, which the runner reloads, checks after init and shows errors from.
//
// A lesson is made before the GL context exists (its steps and parameters are needed for --help,
// --list-params and the scene's settings), so the effects it draws with are Gpu<T> members: the
// runner builds them once the context is current and the scene is loaded, before init().
#include <concepts>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "app/lesson_facts.hpp"
#include "base/params.hpp"
#include "base/result.hpp"
#include "effects/scene/scene_work.hpp"
#include "effects/scene/world.hpp"
#include "render/frame_graph.hpp"
#include "scene/scene.hpp"

namespace fx {

struct LessonInfo {
    int number = 0;     // from the lesson's folder (lessons/01_program_objects)
    std::string slug;   // "program-objects", from the folder: the executable is fxlab-01-program-objects
    std::string title;  // "Program objects"
    std::string defaultScene;  // relative to res/: "scenes/01_program_objects.json"; "": an empty scene
};

// The mouse, in framebuffer pixels with the origin at the bottom left (as GL counts them).
struct Pointer {
    bool present = false;  // a window with the cursor inside it
    float x = 0, y = 0;
    bool leftDown = false;  // held this frame
    bool overUi = false;    // the overlay owns the mouse: lessons ignore it then
};

// The clock and the frame, as a lesson sees them. Time is the lesson clock's (app/lesson_clock.hpp):
// one fixed step a frame, in a window as headless, 0 while the clock is paused.
struct FrameInfo {
    std::uint64_t index = 0;
    double seconds = 0;  // scene time, wrapped by lessons that feed it to shaders
    // The scene, its meshes on the GPU (posed at `seconds`) and the time, as one value for the effects
    // that draw the scene (effects/scene/world.hpp). The runner makes the meshes and skins them.
    World world;
    double deltaSeconds = 0;
    // The lesson clock's fixed steps so far, this frame's included (headless: index + 1). Something a
    // step does every Nth frame counts these, so a paused clock or a slow window changes nothing.
    std::uint64_t clockSteps = 0;
    // In a window: what one frame may cost (ms, app/picture_scale.hpp). Work that takes longer (an
    // accumulated reference) spreads itself over several frames. 0 headless: all of it in one frame.
    double frameBudgetMs = 0;
    Size2D size;
    int step = 0;  // 0-based
    std::uint32_t seed = 1;
    bool headless = false;
    // The last frame's passes and times, if any (in Lesson::facts after the run: the last frame's).
    const FrameReport* previousFrame = nullptr;
    bool benchmark = false;  // a bench frame: leave out views and diagnostics that only help people
    Pointer pointer;
};

class Lesson {
public:
    Lesson();  // its Gpu<T> members join it while it is made
    virtual ~Lesson();
    Lesson(const Lesson&) = delete;
    Lesson& operator=(const Lesson&) = delete;

    // Who the lesson is: the number and slug come from its folder, the title and scene from FX_LESSON.
    const LessonInfo& info() const { return info_; }
    void setInfo(LessonInfo info) { info_ = std::move(info); }  // the runner, before anything else
    // The steps' titles, in the chapter's order. The steps drive the code, so the list lives here;
    // each step's text is its "## Step N: <title>" section of lesson.md (app/lesson_text_files.hpp),
    // and a heading whose title differs from this one is an error.
    virtual std::vector<std::string> steps() const = 0;
    // Called once before the context exists, so --param and --list-params work without GL.
    virtual void declareParams(ParamSet& params) { (void)params; }

    // The GL context is current, the scene loaded and every Gpu<T> member built: what the chapter
    // decides once (a light list, a shadow setting from the scene). A program that does not build
    // fails the run after init, with its error; no need to check here.
    virtual Status init(const Scene& scene) {
        (void)scene;
        return Status::success();
    }

    // The per-frame simulations the lesson runs (skinning, particles, clouds), each under the scene
    // feature it exists for: work.onUpdate(Simulation::animation, "skinning", ...). The runner calls
    // the ones the scene calls for every frame, before update(), and never the others.
    virtual void simulations(SceneWork& work) { (void)work; }
    // Anything else the lesson does once a frame before declaring it (a drag, a clock of its own).
    virtual void update(const FrameInfo& frame) { (void)frame; }
    // Declares this frame's passes for the current step. Their bodies run after this returns, so
    // they capture handles and values by copy, never a local by reference (docs/frame-graph.md).
    // A pass that exists for a scene feature
    // says so (needs(pass, SceneFeature::bloom), effects/scene/scene_work.hpp): the graph then marks
    // it not called for, with the scene's reason, when the scene lacks the feature.
    virtual void buildFrame(FrameGraph& graph, const FrameInfo& frame) = 0;

    // What the lesson computes or measures about `frame`, once: the overlay shows the list under
    // the lesson's panel every frame, and the report writes it for the last frame of the run.
    virtual void facts(Facts& out, const FrameInfo& frame) const { (void)out, (void)frame; }
    // The lesson's own panel in the overlay (ImGui calls), under its steps, parameters and facts:
    // explanations and widgets, not numbers (those are facts).
    virtual void drawPanel(const FrameInfo& frame) { (void)frame; }
    // The step (0-based) whose frame the bench measures, where the quality knobs matter; -1: the
    // step the run starts at.
    virtual int benchStep() const { return -1; }
    // The texture the lesson's effect writes (e.g. "radial_blur.color"); the bench measures its error
    // against the reference too, not only the final image's. Empty: the final image only.
    virtual std::string benchTexture() const { return {}; }
    // A lesson whose right answer is another algorithm than any setting of its knobs (bloom: a direct
    // full-resolution Gaussian instead of the chain) names it here and renders it while the bench
    // has setBenchReference(true). The bench then measures every knob value with the lesson's own
    // algorithm, the knobs' reference value included, and adds the reference algorithm as one more
    // row per knob. Empty (the default): the reference is the knobs' reference setting.
    virtual std::string benchReferenceName() const { return {}; }
    virtual void setBenchReference(bool on) { (void)on; }

    // The runner: builds every Gpu<T> member, in the order they are declared, with the context current
    // and `scene` loaded. Once only.
    void buildGpuMembers(const Scene& scene);

private:
    template <class T>
    friend class Gpu;
    // The lesson whose constructor runs on this thread (set by Lesson(), cleared once its members are
    // built or it goes): where a Gpu<T> member registers.
    static Lesson*& underConstruction();
    LessonInfo info_;
    std::vector<std::function<void(const Scene&)>> gpuMembers_;
    bool gpuMembersBuilt_ = false;
};

// Stops the program with `what` (a Gpu<T> used before the runner built it, or made outside a lesson):
// a mistake in the lesson's code, not in its input.
[[noreturn]] void gpuMemberMisuse(const char* what);

// A member of a lesson that needs the GL context: an effect, a mesh, a buffer. The runner builds it
// right before init(), with the context current:
//
//   fx::Gpu<fx::BloomChain> chain_;                      // BloomChain()
//   fx::Gpu<fx::PlanarReflection> reflection_;           // PlanarReflection(scene): it takes the scene
//   fx::Gpu<fx::FullscreenPass> copy_{"common/copy.frag", "copy"};   // these arguments, kept until then
//   fx::Gpu<fx::GpuParticles> pool_{[this](const fx::Scene&) { return fx::GpuParticles(system_); }};
//
// and the lesson uses it like a pointer: chain_->declare(graph, ...). It goes with the lesson, while
// the context is still current. Only a lesson's members can be Gpu<T> (they join the lesson being made).
template <class T>
class Gpu {
public:
    // T(scene) when T is made from the scene, T() otherwise.
    Gpu() {
        join([this](const Scene& scene) {
            if constexpr (std::is_constructible_v<T, const Scene&>)
                value_.emplace(scene);
            else
                value_.emplace();
        });
    }
    // T made by `make(scene)`, called when the runner builds it (members declared before this one are
    // built already).
    template <class Make>
    requires std::is_invocable_r_v<T, Make, const Scene&>
    explicit Gpu(Make make) {
        join([this, make](const Scene& scene) { value_.emplace(make(scene)); });
    }
    // T(args...), with copies of the arguments kept until then.
    template <class First, class... Rest>
    requires(!std::is_invocable_v<First, const Scene&> &&
             std::is_constructible_v<T, First, Rest...>) explicit Gpu(First first, Rest... rest) {
        join([this, first, rest...](const Scene&) { value_.emplace(first, rest...); });
    }
    Gpu(const Gpu&) = delete;
    Gpu& operator=(const Gpu&) = delete;

    T* operator->() { return &get(); }
    const T* operator->() const { return &get(); }
    T& operator*() { return get(); }
    const T& operator*() const { return get(); }

private:
    void join(std::function<void(const Scene&)> build) {
        Lesson* lesson = Lesson::underConstruction();
        if (!lesson) gpuMemberMisuse("a Gpu<T> made outside a lesson's constructor");
        lesson->gpuMembers_.push_back(std::move(build));
    }
    T& get() {
        if (!value_) gpuMemberMisuse("a Gpu<T> used before the runner built it");
        return *value_;
    }
    const T& get() const {
        if (!value_) gpuMemberMisuse("a Gpu<T> used before the runner built it");
        return *value_;
    }
    std::optional<T> value_;
};

}  // namespace fx
