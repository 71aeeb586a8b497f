#include "scene/clip_selection.hpp"

#include <algorithm>
#include <vector>

#include "base/log.hpp"
#include "base/message_text.hpp"
#include "scene/closest_name.hpp"
#include "scene/scene_limits.hpp"

namespace fx {
namespace {

std::string listOf(const std::vector<std::string>& names) {
    std::string list;
    for (const auto& name : names) list += (list.empty() ? "" : ", ") + name;
    return list;
}

}  // namespace

Result<AnimationClip> selectClips(const GltfModel& model, const Animation& animation) {
    if (model.clips.empty()) return Error{"has no animation clips"};
    std::vector<const AnimationClip*> chosen;
    if (animation.playsAllClips()) {
        for (const auto& clip : model.clips) chosen.push_back(&clip);
    } else {
        std::vector<std::string> available;
        for (const auto& clip : model.clips) available.push_back(clip.name);
        for (const std::string& name : animation.clips) {
            const AnimationClip* clip = model.findClip(name);
            if (!clip) {
                std::string hint;
                if (auto near = closestName(name, available)) hint = cat(" (did you mean \"", *near, "\"?)");
                return Error{
                    cat("has no clip \"", excerpt(name), "\"", hint, "; its clips: ", listOf(available))};
            }
            chosen.push_back(clip);
        }
    }
    if (chosen.size() == 1) return *chosen[0];
    AnimationClip merged;
    for (const AnimationClip* clip : chosen) {
        merged.name += (merged.name.empty() ? "" : " + ") + clip->name;
        merged.channels.insert(merged.channels.end(), clip->channels.begin(), clip->channels.end());
        merged.duration = std::max(merged.duration, clip->duration);
    }
    return merged;
}

}  // namespace fx
