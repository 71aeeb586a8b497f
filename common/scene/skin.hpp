#pragma once
// Skinning on the CPU: the node hierarchy's world matrices for a pose, a skin's joint matrices, and
// the blended skinning of one vertex. The GPU does the same per vertex (shaders/common/skinning.glsl);
// these functions are its reference, and the tests compare the two.
//
// A joint matrix takes a vertex from the skinned mesh's bind space to where the joint has moved it,
// expressed in the space of the node that holds the mesh:
//     jointMatrix[i] = inverse(meshNodeWorld) * jointWorld[i] * inverseBind[i]
// so the mesh is drawn with the model matrix of its node, like any other mesh.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "scene/animation.hpp"

namespace fx {

// One node of a model's hierarchy (what the skeleton and the meshes hang from).
struct ModelNode {
    std::string name;
    int parent = -1;  // -1 for a root
    std::vector<int> children;
    NodeTransform rest;      // the transform in the file, which animation overrides
    bool hasMatrix = false;  // the file gives a matrix instead of TRS (then not animatable)
    glm::mat4 matrix{1.0f};  // used when hasMatrix
    int mesh = -1;           // index into the model's meshes, or -1
    int skin = -1;           // index into the model's skins, or -1

    bool operator==(const ModelNode&) const = default;
};

struct Skin {
    std::string name;
    std::vector<int> joints;                     // node indices; a vertex's joint i means joints[i]
    std::vector<glm::mat4> inverseBindMatrices;  // one per joint (identity when the file has none)

    std::size_t jointCount() const { return joints.size(); }
    bool operator==(const Skin&) const = default;
};

// The rest pose of every node (what animation starts from).
std::vector<NodeTransform> restPose(const std::vector<ModelNode>& nodes);

// Local matrix of node i in a pose (the node's own matrix if the file gave one).
glm::mat4 localMatrix(const std::vector<ModelNode>& nodes, const std::vector<NodeTransform>& pose,
                      std::size_t i);

// World (model-space) matrices of every node: parent's world times the node's local matrix. A
// hierarchy with a cycle (a broken file) would recurse forever; nodes on a cycle get their local matrix.
std::vector<glm::mat4> worldMatrices(const std::vector<ModelNode>& nodes,
                                     const std::vector<NodeTransform>& pose);

// The joint matrices of `skin` for the given world matrices, relative to the node that holds the mesh.
// A joint index outside the hierarchy gives the identity.
std::vector<glm::mat4> jointMatrices(const Skin& skin, const std::vector<glm::mat4>& world,
                                     const glm::mat4& meshNodeWorld);

// Four joint influences of a vertex, as stored in the file (joint indices into the skin).
struct JointInfluence {
    std::uint16_t joints[4] = {0, 0, 0, 0};
    glm::vec4 weights{0.0f};

    bool operator==(const JointInfluence&) const = default;
};

// Below this total weight a vertex counts as unweighted.
inline constexpr float kMinTotalWeight = 1e-6f;

// The blended matrix sum(w_i * M[j_i]) with the weights renormalised to sum to 1. Joints outside
// the palette and negative weights count as weight 0. When nothing is left (all weights 0) the
// vertex keeps its bind pose: the identity, and `unweighted` (if given) is set, instead of the zero
// matrix that would collapse the vertex to the origin (w = 0). The shader follows the same rule.
glm::mat4 blendJoints(const JointInfluence& influence, std::span<const glm::mat4> palette,
                      bool* unweighted = nullptr);

struct SkinnedVertex {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f};
};

// One vertex skinned on the CPU: the reference the GPU's result is compared with. The normal goes
// through the blended matrix's upper 3x3 and is normalised when it is not zero.
SkinnedVertex skinVertex(const glm::vec3& position, const glm::vec3& normal, const JointInfluence& influence,
                         std::span<const glm::mat4> palette, bool* unweighted = nullptr);

}  // namespace fx
