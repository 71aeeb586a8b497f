#pragma once
// Which of a glTF file's animation clips an object plays (scene objects' "animation.clip"): one by name,
// several, or every clip ("*"). Several clips play as one: their channels together, looping at the
// longest clip's length (a shorter clip holds its last key until the loop starts again). A name the file
// does not have is refused with the clips it does have and the nearest one.
#include <string>

#include "base/result.hpp"
#include "scene/gltf_model.hpp"
#include "scene/scene_object.hpp"

namespace fx {

// The clip to play, or an error without the file's name ("has no clip 'wlak' (did you mean "walk"?);
// its clips: walk, wave"). `animation` must name at least one clip.
Result<AnimationClip> selectClips(const GltfModel& model, const Animation& animation);

}  // namespace fx
