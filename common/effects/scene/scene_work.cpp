#include "effects/scene/scene_work.hpp"

#include "base/log.hpp"

namespace fx {

std::string_view toString(Simulation simulation) {
    switch (simulation) {
        case Simulation::animation:
            return "animation";
        case Simulation::particles:
            return "particles";
        case Simulation::clouds:
            return "clouds";
        case Simulation::motion:
            return "motion";
    }
    return "?";
}

SceneFeature featureOf(Simulation simulation) {
    switch (simulation) {
        case Simulation::animation:
            return SceneFeature::skinnedMeshes;
        case Simulation::particles:
            return SceneFeature::particles;
        case Simulation::clouds:
            return SceneFeature::clouds;
        case Simulation::motion:
            return SceneFeature::movingObjects;
    }
    return SceneFeature::skinnedMeshes;
}

namespace {

constexpr SceneFeature kEveryFeature[] = {
    SceneFeature::skinnedMeshes, SceneFeature::shadows,       SceneFeature::particles,
    SceneFeature::clouds,        SceneFeature::hdrEmissive,   SceneFeature::physicalLens,
    SceneFeature::manyLights,    SceneFeature::movingObjects, SceneFeature::bloom,
    SceneFeature::colorMatrix,   SceneFeature::radialBlur,    SceneFeature::depthOfField,
    SceneFeature::toneMap,       SceneFeature::mirror,
};

}  // namespace

std::string requirementName(SceneFeature feature) {
    return cat("scene feature ", static_cast<int>(feature));
}

Pass& needs(Pass& pass, SceneFeature feature) {
    return pass.needs(requirementName(feature));
}

PassGroup groupNeeding(SceneFeature feature) {
    PassGroup group;
    group.needing(requirementName(feature));
    return group;
}

const std::string* lacks(const FrameGraph& graph, SceneFeature feature) {
    return graph.unmetReason(requirementName(feature));
}

void SceneWork::describeTo(FrameGraph& graph) const {
    for (SceneFeature feature : kEveryFeature) {
        if (!has(feature)) graph.setUnmet(requirementName(feature), missingReason(feature));
    }
}

void SceneWork::onUpdate(Simulation simulation, std::string name,
                         std::function<void(const SimulationStep&)> update) {
    updates_.push_back({simulation, std::move(name), std::move(update)});
}

void SceneWork::update(double seconds, double deltaSeconds) {
    records_.clear();
    SimulationStep step{seconds, deltaSeconds};
    for (const Registered& r : updates_) {
        SimulationRecord record{r.simulation, r.name, runs(r.simulation), {}};
        if (record.ran) {
            if (r.update) r.update(step);
        } else {
            record.reason = whyNot(r.simulation);
        }
        records_.push_back(std::move(record));
    }
}

std::vector<std::string> SceneWork::ranLastUpdate() const {
    std::vector<std::string> names;
    for (const auto& r : records_)
        if (r.ran) names.push_back(r.name);
    return names;
}

}  // namespace fx
