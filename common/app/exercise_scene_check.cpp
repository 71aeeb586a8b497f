#include "app/exercise_scene_check.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "base/log.hpp"
#include "base/words.hpp"
#include "effects/particles/particle_system.hpp"
#include "scene/scene_loader.hpp"

namespace fx {
namespace {

namespace fs = std::filesystem;

bool finite(const glm::vec4& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
}

// The first hint written for `when`, or "".
std::string hintFor(const Exercise& exercise, const std::string& when) {
    for (const ExerciseHint& hint : exercise.hints)
        if (hint.when == when) return hint.text;
    return {};
}

}  // namespace

ExerciseVerdict checkSceneExercise(const Exercise& exercise, const fs::path& studentFile) {
    ExerciseVerdict verdict;
    verdict.measure = exercise.measure;
    verdict.tolerance = exercise.tolerance;
    auto fail = [&](const std::string& when, std::string message) {
        verdict.message = std::move(message);
        verdict.hint = hintFor(exercise, when);
        if (verdict.hint.empty()) verdict.hint = hintFor(exercise, "fails");
        return verdict;
    };
    SceneLoadOptions options;
    options.loadModels = false;  // only the emitters are checked
    auto scene = loadScene(studentFile, options);
    if (!scene) {
        verdict.error = scene.error();
        verdict.measured = std::numeric_limits<double>::infinity();
        return fail("invalid", say("check.sceneDidNotLoad", {{"error", scene.error()}}));
    }
    if (scene->emitters.empty())
        return fail("noEmitter", say("check.noEmitter", {{"file", studentFile.string()}}));

    // Judged from the scene first: the particles it keeps alive at once (each emitter's rate x its
    // lifetime, within the check's seconds). Clearly past the budget, it fails without being simulated,
    // so a scene at the format's limits (256 emitters at 100000 particles each) costs neither minutes
    // nor gigabytes; near the budget the simulation decides.
    double asked = 0.0;
    for (const ParticleEmitter& emitter : scene->emitters)
        asked += std::ceil(double(emitter.ratePerSecond) *
                           std::min(double(emitter.lifetimeSeconds), double(exercise.seconds)));
    if (asked > 2.0 * exercise.budget) {
        verdict.measured = asked;
        return fail("overBudget",
                    cat("about ", std::uint64_t(asked), " particles alive at once (rate x lifetime over ",
                        scene->emitters.size(), " emitter", scene->emitters.size() == 1 ? "" : "s",
                        " in the first ", exercise.seconds, " s), needs <= ", std::uint32_t(exercise.budget),
                        "; judged from your scene without simulating it"));
    }

    std::vector<EmitterSetup> setups;
    for (const ParticleEmitter& emitter : scene->emitters) setups.push_back({emitter, {}, 0, 1.0f, false});
    ParticleSystem system(std::move(setups));
    const int frames = int(std::ceil(exercise.seconds * 60.0));
    std::uint32_t peak = 0;
    std::string firstNonFinite;
    for (int frame = 0; frame < frames; ++frame) {
        system.update(1.0 / 60.0);
        peak = std::max(peak, system.liveCount());
        for (std::size_t slot = 0; slot < system.slots().size(); ++slot) {
            const GpuParticle& p = system.slots()[slot];
            if (p.extra.z == 0.0f) continue;
            const glm::vec4 position(glm::vec3(p.originAge) + glm::vec3(p.velocityLife) * p.originAge.w,
                                     1.0f);
            if (finite(p.originAge) && finite(p.velocityLife) && finite(p.extra) && finite(position))
                continue;
            if (verdict.nonFiniteTexels++ == 0)
                firstNonFinite =
                    say("check.particleAt",
                        {{"slot", cat(slot)}, {"emitter", cat(int(p.extra.y))}, {"frame", cat(frame + 1)}});
        }
    }
    verdict.measured = peak;
    const auto budget = std::uint32_t(exercise.budget);
    verdict.message = say(scene->emitters.size() == 1 ? "check.peakOne" : "check.peakMany",
                          {{"peak", cat(peak)},
                           {"measures", exercise.measures},
                           {"budget", cat(budget)},
                           {"emitters", cat(scene->emitters.size())},
                           {"seconds", cat(exercise.seconds)}});
    if (system.droppedCount() > 0 || system.replacedCount() > 0)
        verdict.message +=
            say("check.ringFull", {{"count", cat(system.replacedCount() + system.droppedCount())}});
    if (verdict.nonFiniteTexels > 0) {
        verdict.message += say("check.particleNonFinite",
                               {{"count", cat(verdict.nonFiniteTexels)}, {"first", firstNonFinite}});
        return fail("nonFinite", verdict.message);
    }
    if (peak > budget) return fail("overBudget", verdict.message);
    if (peak == 0) return fail("noEmitter", verdict.message + say("check.neverAlive"));
    verdict.passed = true;
    return verdict;
}

}  // namespace fx
