#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "geometry/mesh_data.hpp"

using namespace fx;

namespace {

// Every triangle's winding agrees with its vertex normals (counter-clockwise seen from outside), and
// every index is in range.
void expectConsistent(const MeshData& m) {
    ASSERT_EQ(m.positions.size(), m.normals.size());
    ASSERT_EQ(m.positions.size(), m.uvs.size());
    ASSERT_EQ(m.indices.size() % 3, 0u);
    for (std::size_t t = 0; t < m.indices.size(); t += 3) {
        for (int k = 0; k < 3; ++k) ASSERT_LT(m.indices[t + k], m.positions.size());
        glm::vec3 a = m.positions[m.indices[t]], b = m.positions[m.indices[t + 1]],
                  c = m.positions[m.indices[t + 2]];
        glm::vec3 face = glm::cross(b - a, c - a);
        if (glm::length(face) < 1e-5f) continue;  // collapsed at a pole
        glm::vec3 n = m.normals[m.indices[t]] + m.normals[m.indices[t + 1]] + m.normals[m.indices[t + 2]];
        EXPECT_GT(glm::dot(face, n), 0.0f) << "triangle " << t / 3 << " faces inward";
    }
    for (auto& n : m.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
}

}  // namespace

TEST(Primitives, PlaneFacesUp) {
    auto m = makePlane(4, 2);
    expectConsistent(m);
    EXPECT_EQ(m.triangleCount(), 2u);
    for (auto& p : m.positions) EXPECT_EQ(p.y, 0.0f);
}

TEST(Primitives, BoxHasTheRequestedExtent) {
    auto m = makeBox({2, 4, 6});
    expectConsistent(m);
    EXPECT_EQ(m.triangleCount(), 12u);
    glm::vec3 hi(-1e9f);
    for (auto& p : m.positions) hi = glm::max(hi, p);
    EXPECT_EQ(hi, glm::vec3(1, 2, 3));
}

TEST(Primitives, SphereVerticesLieOnTheRadius) {
    auto m = makeSphere(2.0f, 12, 6);
    expectConsistent(m);
    for (auto& p : m.positions) EXPECT_NEAR(glm::length(p), 2.0f, 1e-5f);
    EXPECT_EQ(m.triangleCount(), 12u * 6u * 2u);
}

TEST(Primitives, CylinderAndCapsuleAreClosedAndOutwardFacing) {
    expectConsistent(makeCylinder(0.5f, 2.0f, 16));
    auto capsule = makeCapsule(0.5f, 3.0f, 16, 4);
    expectConsistent(capsule);
    float top = -1e9f, bottom = 1e9f;
    for (auto& p : capsule.positions) {
        top = std::max(top, p.y);
        bottom = std::min(bottom, p.y);
    }
    EXPECT_NEAR(top, 1.5f, 1e-5f);
    EXPECT_NEAR(bottom, -1.5f, 1e-5f);
}

TEST(Primitives, DegenerateCountsAreRaisedToTheMinimum) {
    auto m = makeSphere(1.0f, 0, 0);
    expectConsistent(m);
    EXPECT_GT(m.triangleCount(), 0u);
}
