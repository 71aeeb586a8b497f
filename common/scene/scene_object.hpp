#pragma once
// Things drawn in a scene: a built-in primitive or a glTF model, placed by a transform, with a material,
// an optional animation clip (glTF only) and an optional simple motion.
#include <optional>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "scene/asset_ref.hpp"

namespace fx {

enum class PrimitiveShape { plane, box, sphere, cylinder, capsule };

// Dimensions in metres, centred on the object's origin. Each shape reads only its own fields.
struct Primitive {
    PrimitiveShape shape = PrimitiveShape::box;
    glm::vec2 planeSize{10.0f, 10.0f};  // plane: extent along X and Z; it faces +Y
    glm::vec3 boxSize{1.0f};            // box: full extent along X, Y, Z
    float radius = 0.5f;                // sphere, cylinder, capsule
    float height = 1.0f;                // cylinder; capsule (total, caps included, at least 2 radius)

    bool operator==(const Primitive&) const = default;
};

struct Transform {
    glm::vec3 position{0.0f};
    glm::vec3 rotationDegrees{0.0f};  // Euler angles, applied X first, then Y, then Z
    glm::vec3 scale{1.0f};            // every component > 0

    bool operator==(const Transform&) const = default;
};

struct Material {
    glm::vec3 baseColor{0.8f};  // linear albedo in [0, 1]
    AssetRef baseColorTexture;  // multiplies baseColor when set
    glm::vec3 emissive{0.0f};   // linear HDR colour; components above 1 are what bloom picks up
    float emissiveStrength = 1.0f;

    // The light the surface emits: emissive colour times strength.
    glm::vec3 emitted() const { return emissive * emissiveStrength; }
    bool operator==(const Material&) const = default;
};

// Clips from the object's glTF file, played together: one name, several (a file that keeps one clip per
// joint), or {"*"} for every clip the file has. No names means no animation.
struct Animation {
    std::vector<std::string> clips;
    float speed = 1.0f;  // playback rate; negative plays backwards

    bool playsAllClips() const { return clips.size() == 1 && clips[0] == "*"; }
    bool operator==(const Animation&) const = default;
};

enum class MotionType { none, circle, bob };

// A simple scripted movement around the object's position, so a scene can have something moving without
// a glTF animation: `circle` goes round a horizontal circle, `bob` goes up and down.
struct Motion {
    MotionType type = MotionType::none;
    float radius = 1.0f;         // circle
    float amplitude = 0.25f;     // bob: the highest point above the rest position
    float periodSeconds = 4.0f;  // one full turn or one full bob
    float phaseDegrees = 0.0f;   // where in the cycle the motion starts

    bool operator==(const Motion&) const = default;
};

// A plane that mirrors the scene (lesson 10's planar reflection): the reflection is drawn from the
// camera mirrored in the plane and mixed onto the plane's own colour at `strength`.
struct Mirror {
    float strength = 0.5f;  // [0, 1]: how much of the reflection the surface shows

    bool operator==(const Mirror&) const = default;
};

struct SceneObject {
    std::string name;
    std::optional<Primitive> primitive;  // exactly one of primitive and gltf is set
    AssetRef gltf;
    Transform transform;
    Material material;
    bool castsShadows = true;
    bool receivesShadows = true;
    Animation animation;
    // A glTF object with an animation clip is taken to be skinned. The glTF loader can refine this once it
    // has read the file (a clip may move rigid nodes only).
    bool skinned = false;
    Motion motion;
    std::optional<Mirror> mirror;  // only a plane primitive may be a mirror; at most one per scene

    bool moves() const { return motion.type != MotionType::none; }
    bool operator==(const SceneObject&) const = default;
};

// The offset a motion adds to the object's position at `seconds`. The phase is wrapped into one period
// first, so hours of running time still give small, exact arguments to sin and cos.
glm::vec3 motionOffset(const Motion& motion, double seconds);

// Model matrix: translate * rotate (Z * Y * X) * scale.
glm::mat4 modelMatrix(const Transform& transform);

}  // namespace fx
