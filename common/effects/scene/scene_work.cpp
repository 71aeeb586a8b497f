#include "effects/scene/scene_work.hpp"

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

bool SceneWork::require(Pass& pass, SceneFeature feature) const {
    if (has(feature)) return true;
    pass.notCalledFor(missingReason(feature));
    return false;
}

bool SceneWork::requireAll(Pass& pass, std::initializer_list<SceneFeature> features) const {
    for (SceneFeature feature : features)
        if (!require(pass, feature)) return false;
    return true;
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
