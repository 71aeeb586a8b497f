#pragma once
// What work a scene calls for, in one place for every lesson: which simulations run each frame and
// which passes the frame graph gets. A pass whose feature the scene lacks is still declared (so the
// overlay lists it) but marked "not called for" with the scene's reason, which means it does not run
// and nothing it would create is allocated. A simulation the scene does not call for is never called.
//
// The runner makes one SceneWork for the lesson's scene and tells every frame's graph what the scene
// lacks (describeTo) before the lesson declares; a pass declares what it is for, and the graph does
// the rest:
//
//   SceneWork work(scene);
//   work.onUpdate(Simulation::particles, "fire", [&](const SimulationStep& s) { fire.update(s); });
//   work.update(frame.seconds, frame.deltaSeconds);          // in Lesson::update
//   ...
//   work.describeTo(graph);                                  // the runner, every frame
//   needs(graph.addPass("particles", draw).modify(hdr, TextureUsage::ColorAttachment),
//         SceneFeature::particles);                          // "scene has no particle emitter"
//   if (work.runs(Simulation::particles)) fire.allocate();   // buffers only when there is fire
#include <functional>
#include <string>
#include <vector>

#include "render/frame_graph.hpp"
#include "scene/scene_features.hpp"

namespace fx {

// The name a pass gives the graph for a feature it needs ("scene:bloom").
std::string requirementName(SceneFeature feature);
// The pass exists for `feature`: when the graph was told the scene lacks it, the pass is not called
// for, with the scene's reason.
Pass& needs(Pass& pass, SceneFeature feature);
// A pass group whose passes all need `feature` (PassGroup::needing).
PassGroup groupNeeding(SceneFeature feature);
// Why the frame's scene lacks `feature` (as told to the graph); nullptr when it has it.
const std::string* lacks(const FrameGraph& graph, SceneFeature feature);

// The per-frame simulations a scene can need.
enum class Simulation {
    animation,  // skeletal animation and GPU skinning (skinned meshes)
    particles,  // particle emitters
    clouds,     // cloud layers scrolling their noise
    motion,     // objects with a simple scripted motion
};

std::string_view toString(Simulation simulation);
// The scene feature a simulation exists for.
SceneFeature featureOf(Simulation simulation);

struct SimulationStep {
    double seconds = 0;       // scene time
    double deltaSeconds = 0;  // since the last update
};

// One registered update and what happened to it in the last SceneWork::update.
struct SimulationRecord {
    Simulation simulation = Simulation::animation;
    std::string name;
    bool ran = false;
    std::string reason;  // why not, when it did not run
};

class SceneWork {
public:
    SceneWork() = default;
    explicit SceneWork(const Scene& scene) : SceneWork(fx::features(scene)) {}
    explicit SceneWork(SceneFeatures features) : features_(std::move(features)) {}

    const SceneFeatures& features() const { return features_; }
    bool has(SceneFeature feature) const { return features_.has(feature); }
    std::string missingReason(SceneFeature feature) const { return features_.missingReason(feature); }

    // --- Passes ---
    // Tells the graph every feature the scene lacks, with its reason (FrameGraph::setUnmet).
    void describeTo(FrameGraph& graph) const;

    // --- Simulations ---
    bool runs(Simulation simulation) const { return has(featureOf(simulation)); }
    std::string whyNot(Simulation simulation) const { return missingReason(featureOf(simulation)); }
    // Registers an update; update() calls it only while the scene calls for its simulation.
    void onUpdate(Simulation simulation, std::string name, std::function<void(const SimulationStep&)> update);
    // Runs the registered updates the scene calls for, in registration order, and records the others
    // with their reasons (lastUpdate()).
    void update(double seconds, double deltaSeconds);
    const std::vector<SimulationRecord>& lastUpdate() const { return records_; }
    // Simulations that ran in the last update, by name.
    std::vector<std::string> ranLastUpdate() const;

private:
    struct Registered {
        Simulation simulation;
        std::string name;
        std::function<void(const SimulationStep&)> update;
    };
    SceneFeatures features_;
    std::vector<Registered> updates_;
    std::vector<SimulationRecord> records_;
};

}  // namespace fx
