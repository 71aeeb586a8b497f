#pragma once
// Keyframe animation as glTF stores it: a clip is a set of channels, each moving one property
// (translation, rotation or scale) of one node through keyframes. Sampling is pure arithmetic on the
// CPU; the joint matrices it leads to (skin.hpp) are what the GPU receives.
//
//   float t = clipTime(frame.seconds * speed, clip.duration);  // wrapped: hours of play stay exact
//   std::vector<NodeTransform> pose = restPose(model.nodes);
//   applyClip(clip, t, pose);
#include <string>
#include <vector>

#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace fx {

// A node's local transform as translation, rotation and scale: matrix = T * R * S.
struct NodeTransform {
    glm::vec3 translation{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};  // glm order: w, x, y, z
    glm::vec3 scale{1.0f};

    glm::mat4 matrix() const;
    bool operator==(const NodeTransform&) const = default;
};

enum class AnimatedProperty { translation, rotation, scale };
// glTF's three interpolations. A cubic-spline channel stores three values per key: in-tangent,
// value, out-tangent (in that order, as in the file).
enum class Interpolation { linear, step, cubicSpline };

struct AnimationChannel {
    int node = -1;
    AnimatedProperty property = AnimatedProperty::translation;
    Interpolation interpolation = Interpolation::linear;
    std::vector<float> times;       // seconds, increasing
    std::vector<glm::vec4> values;  // xyz for translation and scale; rotation quaternions as (x, y, z, w)

    bool operator==(const AnimationChannel&) const = default;
};

struct AnimationClip {
    std::string name;
    std::vector<AnimationChannel> channels;
    float duration = 0.0f;  // the last key time over all channels

    bool operator==(const AnimationClip&) const = default;
};

// The channel's value at `time` (seconds into the clip). Before the first key it holds the first
// value, after the last key the last value. Linear rotations use the shortest-path slerp and come
// out normalised. Two keys at the same time do not divide by zero: the later key wins. A channel
// without keys gives (0, 0, 0, 0) for translation, the identity for rotation and 1 for scale.
glm::vec4 sampleChannel(const AnimationChannel& channel, float time);

// Seconds of playback (already multiplied by the speed, may be negative or huge) to a time inside
// [0, duration): the clip loops. A clip without length, or a time that is not finite, gives 0.
float clipTime(double playbackSeconds, float duration);

// Writes every channel of `clip` at `time` into `pose` (indexed by node). Channels that name a node
// outside `pose` are ignored.
void applyClip(const AnimationClip& clip, float time, std::vector<NodeTransform>& pose);

// Rotation quaternion from a sampled (x, y, z, w) value, normalised; a zero quaternion is the identity.
glm::quat toQuat(const glm::vec4& xyzw);

}  // namespace fx
