// The CPU side of skinning: world matrices down a hierarchy, joint matrices from inverse bind matrices,
// and the blend of four influences with the guard for vertices whose weights add up to nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/skin.hpp"

namespace {

bool near(const glm::mat4& a, const glm::mat4& b, float tolerance = 1e-5f) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (std::abs(a[c][r] - b[c][r]) > tolerance) return false;
    return true;
}

// root (translated up 1) -> arm (moved 2 along X, rotated by the pose) -> hand (1 further along X).
std::vector<fx::ModelNode> chain() {
    std::vector<fx::ModelNode> nodes(3);
    nodes[0].rest.translation = {0, 1, 0};
    nodes[0].children = {1};
    nodes[1].parent = 0;
    nodes[1].rest.translation = {2, 0, 0};
    nodes[1].children = {2};
    nodes[2].parent = 1;
    nodes[2].rest.translation = {1, 0, 0};
    return nodes;
}

TEST(SkinHierarchy, WorldMatricesComposeParentFirst) {
    auto nodes = chain();
    auto pose = fx::restPose(nodes);
    pose[1].rotation = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 0, 1));  // the arm points up
    auto world = fx::worldMatrices(nodes, pose);
    glm::vec3 hand(world[2] * glm::vec4(0, 0, 0, 1));
    EXPECT_NEAR(hand.x, 2.0f, 1e-6f);
    EXPECT_NEAR(hand.y, 2.0f, 1e-6f);  // 1 (root) + 1 (hand offset turned to +Y)
    EXPECT_NEAR(hand.z, 0.0f, 1e-6f);
}

TEST(SkinHierarchy, ANodeMatrixOverridesItsTransform) {
    auto nodes = chain();
    nodes[2].hasMatrix = true;
    nodes[2].matrix = glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, 5));
    auto world = fx::worldMatrices(nodes, fx::restPose(nodes));
    EXPECT_TRUE(near(world[2], glm::translate(glm::mat4(1.0f), glm::vec3(2, 1, 5))));
}

TEST(SkinHierarchy, ACycleDoesNotHang) {
    auto nodes = chain();
    nodes[0].parent = 2;  // broken file: 0 -> 1 -> 2 -> 0
    auto world = fx::worldMatrices(nodes, fx::restPose(nodes));
    ASSERT_EQ(world.size(), 3u);
    for (const auto& m : world) EXPECT_TRUE(std::isfinite(m[3][0]));
}

TEST(SkinJoints, InverseBindMatricesGiveIdentityAtRest) {
    auto nodes = chain();
    auto world = fx::worldMatrices(nodes, fx::restPose(nodes));
    fx::Skin skin;
    skin.joints = {1, 2};
    for (int j : skin.joints) skin.inverseBindMatrices.push_back(glm::inverse(world[std::size_t(j)]));
    auto joints = fx::jointMatrices(skin, world, glm::mat4(1.0f));
    ASSERT_EQ(joints.size(), 2u);
    for (const auto& m : joints) EXPECT_TRUE(near(m, glm::mat4(1.0f)));
}

TEST(SkinJoints, MovedJointCarriesItsVerticesAndTheMeshNodeIsFactoredOut) {
    auto nodes = chain();
    auto rest = fx::worldMatrices(nodes, fx::restPose(nodes));
    fx::Skin skin;
    skin.joints = {1};
    skin.inverseBindMatrices = {glm::inverse(rest[1])};
    auto pose = fx::restPose(nodes);
    pose[1].rotation = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 0, 1));
    auto world = fx::worldMatrices(nodes, pose);
    // The mesh hangs from a node placed at (0, 0, 10): joint matrices are relative to it.
    glm::mat4 meshNode = glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, 10));
    auto joints = fx::jointMatrices(skin, world, meshNode);
    // A vertex bound at the hand's rest position (3, 1, 0) follows the arm to (2, 2, 0) in world
    // space, which is (2, 2, -10) in the mesh node's space.
    glm::vec3 v(joints[0] * glm::vec4(3, 1, 0, 1));
    EXPECT_NEAR(v.x, 2.0f, 1e-5f);
    EXPECT_NEAR(v.y, 2.0f, 1e-5f);
    EXPECT_NEAR(v.z, -10.0f, 1e-5f);
}

TEST(SkinJoints, JointsOutsideTheHierarchyGiveIdentity) {
    fx::Skin skin;
    skin.joints = {5};
    skin.inverseBindMatrices = {glm::translate(glm::mat4(1.0f), glm::vec3(1, 2, 3))};
    auto joints = fx::jointMatrices(skin, {glm::mat4(1.0f)}, glm::mat4(1.0f));
    EXPECT_TRUE(near(joints[0], glm::mat4(1.0f)));
}

TEST(SkinBlend, WeightsBlendAndRenormalise) {
    std::vector<glm::mat4> palette = {glm::translate(glm::mat4(1.0f), glm::vec3(2, 0, 0)),
                                      glm::translate(glm::mat4(1.0f), glm::vec3(0, 4, 0))};
    fx::JointInfluence inf;
    inf.joints[0] = 0;
    inf.joints[1] = 1;
    inf.weights = {0.25f, 0.75f, 0, 0};
    bool unweighted = true;
    auto v = fx::skinVertex({0, 0, 0}, {0, 0, 1}, inf, palette, &unweighted);
    EXPECT_FALSE(unweighted);
    EXPECT_NEAR(v.position.x, 0.5f, 1e-6f);
    EXPECT_NEAR(v.position.y, 3.0f, 1e-6f);
    // Weights that add up to 2 are divided by 2: the vertex does not grow (w stays 1).
    inf.weights = {0.5f, 1.5f, 0, 0};
    v = fx::skinVertex({0, 0, 0}, {0, 0, 1}, inf, palette);
    EXPECT_NEAR(v.position.x, 0.5f, 1e-6f);
    EXPECT_NEAR(v.position.y, 3.0f, 1e-6f);
    EXPECT_NEAR(v.normal.z, 1.0f, 1e-6f);
}

TEST(SkinBlend, ZeroWeightsKeepTheBindPose) {
    std::vector<glm::mat4> palette = {glm::translate(glm::mat4(1.0f), glm::vec3(2, 0, 0))};
    fx::JointInfluence inf;  // all weights 0: the chapter's degenerate case (J = 0, w = 0)
    bool unweighted = false;
    glm::mat4 m = fx::blendJoints(inf, palette, &unweighted);
    EXPECT_TRUE(unweighted);
    EXPECT_TRUE(near(m, glm::mat4(1.0f)));
    auto v = fx::skinVertex({1, 2, 3}, {0, 1, 0}, inf, palette);
    EXPECT_EQ(v.position, glm::vec3(1, 2, 3));
    EXPECT_EQ(v.normal, glm::vec3(0, 1, 0));
}

TEST(SkinBlend, OutOfRangeJointsAndNegativeWeightsCountAsZero) {
    std::vector<glm::mat4> palette = {glm::translate(glm::mat4(1.0f), glm::vec3(2, 0, 0))};
    fx::JointInfluence inf;
    inf.joints[0] = 0;
    inf.joints[1] = 9;  // beyond the palette: an out-of-bounds read on the GPU if not guarded
    inf.joints[2] = 0;
    inf.weights = {0.5f, 0.5f, -0.25f, 0};
    auto v = fx::skinVertex({0, 0, 0}, {1, 0, 0}, inf, palette);
    EXPECT_NEAR(v.position.x, 2.0f, 1e-6f);  // all that is left is joint 0, renormalised to 1
    // Only invalid influences: the bind pose.
    inf.weights = {0, 1, 0, 0};
    bool unweighted = false;
    v = fx::skinVertex({0, 0, 0}, {1, 0, 0}, inf, palette, &unweighted);
    EXPECT_TRUE(unweighted);
    EXPECT_EQ(v.position, glm::vec3(0));
    // And an empty palette never reads anything.
    EXPECT_TRUE(near(fx::blendJoints(inf, {}), glm::mat4(1.0f)));
}

TEST(SkinBlend, ANormalThatCollapsesStaysZeroNotNaN) {
    std::vector<glm::mat4> palette = {glm::scale(glm::mat4(1.0f), glm::vec3(0.0f))};
    fx::JointInfluence inf;
    inf.weights = {1, 0, 0, 0};
    auto v = fx::skinVertex({1, 1, 1}, {0, 1, 0}, inf, palette);
    EXPECT_EQ(v.normal, glm::vec3(0));
    EXPECT_EQ(v.position, glm::vec3(0));
}

}  // namespace
