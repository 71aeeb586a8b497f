#include "scene/skin.hpp"

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

namespace fx {

std::vector<NodeTransform> restPose(const std::vector<ModelNode>& nodes) {
    std::vector<NodeTransform> pose;
    pose.reserve(nodes.size());
    for (const ModelNode& node : nodes) pose.push_back(node.rest);
    return pose;
}

glm::mat4 localMatrix(const std::vector<ModelNode>& nodes, const std::vector<NodeTransform>& pose,
                      std::size_t i) {
    if (nodes[i].hasMatrix) return nodes[i].matrix;
    return i < pose.size() ? pose[i].matrix() : nodes[i].rest.matrix();
}

std::vector<glm::mat4> worldMatrices(const std::vector<ModelNode>& nodes,
                                     const std::vector<NodeTransform>& pose) {
    const std::size_t n = nodes.size();
    auto parentOf = [&](std::size_t i) -> std::ptrdiff_t {
        int p = nodes[i].parent;
        return p >= 0 && static_cast<std::size_t>(p) < n ? p : -1;
    };
    std::vector<glm::mat4> world(n, glm::mat4(1.0f));
    for (std::size_t i = 0; i < n; ++i) {
        // Walk up to the root; a chain longer than the node count can only be a cycle.
        glm::mat4 m = localMatrix(nodes, pose, i);
        std::size_t steps = 0;
        for (std::ptrdiff_t p = parentOf(i); p >= 0 && steps <= n;
             p = parentOf(static_cast<std::size_t>(p)), ++steps)
            m = localMatrix(nodes, pose, static_cast<std::size_t>(p)) * m;
        world[i] = steps > n ? localMatrix(nodes, pose, i) : m;
    }
    return world;
}

std::vector<glm::mat4> jointMatrices(const Skin& skin, const std::vector<glm::mat4>& world,
                                     const glm::mat4& meshNodeWorld) {
    glm::mat4 toMesh = glm::inverse(meshNodeWorld);
    std::vector<glm::mat4> result(skin.joints.size(), glm::mat4(1.0f));
    for (std::size_t i = 0; i < skin.joints.size(); ++i) {
        int joint = skin.joints[i];
        if (joint < 0 || static_cast<std::size_t>(joint) >= world.size()) continue;
        glm::mat4 inverseBind =
            i < skin.inverseBindMatrices.size() ? skin.inverseBindMatrices[i] : glm::mat4(1.0f);
        result[i] = toMesh * world[static_cast<std::size_t>(joint)] * inverseBind;
    }
    return result;
}

glm::mat4 blendJoints(const JointInfluence& influence, std::span<const glm::mat4> palette, bool* unweighted) {
    float w[4];
    float total = 0.0f;
    for (int i = 0; i < 4; ++i) {
        bool valid = influence.joints[i] < palette.size() && influence.weights[i] > 0.0f;
        w[i] = valid ? influence.weights[i] : 0.0f;
        total += w[i];
    }
    if (unweighted) *unweighted = !(total > kMinTotalWeight);
    if (!(total > kMinTotalWeight)) return glm::mat4(1.0f);
    glm::mat4 blended(0.0f);
    for (int i = 0; i < 4; ++i) {
        if (w[i] > 0.0f) blended += (w[i] / total) * palette[influence.joints[i]];
    }
    return blended;
}

SkinnedVertex skinVertex(const glm::vec3& position, const glm::vec3& normal, const JointInfluence& influence,
                         std::span<const glm::mat4> palette, bool* unweighted) {
    glm::mat4 m = blendJoints(influence, palette, unweighted);
    SkinnedVertex v;
    v.position = glm::vec3(m * glm::vec4(position, 1.0f));
    glm::vec3 n = glm::mat3(m) * normal;
    float length = glm::length(n);
    v.normal = length > 1e-12f ? n / length : glm::vec3(0.0f);
    return v;
}

}  // namespace fx
