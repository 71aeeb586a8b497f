// The directional light's fitted frustum: it covers what it must, its depth grows along the light,
// and the hard cases (light parallel to up, zero or NaN direction, empty or NaN bounds) stay finite.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "scene/light_frustum.hpp"

using namespace fx;

namespace {

bool finite(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

glm::vec3 ndc(const LightView& light, glm::vec3 p) {
    glm::vec4 c = light.viewProjection * glm::vec4(p, 1.0f);
    return glm::vec3(c) / c.w;
}

Bounds box(glm::vec3 min, glm::vec3 max) {
    Bounds b;
    b.add(min);
    b.add(max);
    return b;
}

void expectCornersInside(const LightView& light, const Bounds& b) {
    for (int i = 0; i < 8; ++i) {
        glm::vec3 corner((i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y,
                         (i & 4) ? b.max.z : b.min.z);
        glm::vec3 p = ndc(light, corner);
        for (int k = 0; k < 3; ++k) {
            EXPECT_GE(p[k], -1.0001f) << "corner " << i << " axis " << k;
            EXPECT_LE(p[k], 1.0001f) << "corner " << i << " axis " << k;
        }
    }
}

}  // namespace

TEST(LightFrustum, CoversTheBoundsWhenUnlimited) {
    Bounds b = box({-3, 0, -2}, {4, 3, 5});
    LightView light = fitLightFrustum(b, {-0.8f, -0.35f, -0.45f}, 0.0f, 2048);
    EXPECT_TRUE(finite(light.viewProjection));
    EXPECT_FALSE(light.fallbackDirection);
    expectCornersInside(light, b);
    EXPECT_NEAR(light.texelWorldSize, 2.0f * light.halfWidth / 2048.0f, 1e-7f);
}

TEST(LightFrustum, DepthGrowsAlongTheLight) {
    glm::vec3 dir = glm::normalize(glm::vec3(-0.8f, -0.35f, -0.45f));
    LightView light = fitLightFrustum(box({-2, -2, -2}, {2, 2, 2}), dir, 0.0f, 1024);
    EXPECT_LT(ndc(light, -dir).z, ndc(light, dir).z);  // nearer the light: smaller depth
    EXPECT_NEAR(glm::dot(light.directionToLight, -dir), 1.0f, 1e-6f);
}

TEST(LightFrustum, ExtentLimitsTheHalfWidth) {
    Bounds ground = box({-15, 0, -15}, {15, 0, 15});
    LightView light = fitLightFrustum(ground, {0.3f, -1.0f, 0.2f}, 5.0f, 512);
    EXPECT_FLOAT_EQ(light.halfWidth, 5.0f);
    EXPECT_NEAR(light.texelWorldSize, 10.0f / 512.0f, 1e-6f);
}

TEST(LightFrustum, LightParallelToUpStaysFinite) {
    Bounds b = box({-1, 0, -1}, {1, 2, 1});
    for (glm::vec3 dir : {glm::vec3(0, -1, 0), glm::vec3(0, 1, 0), glm::vec3(1e-7f, -1, 0)}) {
        LightView light = fitLightFrustum(b, dir, 0.0f, 2048);
        EXPECT_TRUE(finite(light.viewProjection)) << dir.x << " " << dir.y << " " << dir.z;
        EXPECT_FALSE(light.fallbackDirection);
        expectCornersInside(light, b);
    }
}

TEST(LightFrustum, ZeroOrNanDirectionFallsBackToStraightDown) {
    Bounds b = box({-1, 0, -1}, {1, 2, 1});
    float nan = std::numeric_limits<float>::quiet_NaN();
    for (glm::vec3 dir : {glm::vec3(0.0f), glm::vec3(nan, -1, 0)}) {
        LightView light = fitLightFrustum(b, dir, 0.0f, 2048);
        EXPECT_TRUE(light.fallbackDirection);
        EXPECT_TRUE(finite(light.viewProjection));
        EXPECT_NEAR(light.directionToLight.y, 1.0f, 1e-6f);
        expectCornersInside(light, b);
    }
}

TEST(LightFrustum, EmptyOrNanBoundsStayFinite) {
    float nan = std::numeric_limits<float>::quiet_NaN();
    Bounds withNan;
    withNan.add(glm::vec3(nan, 0, 0));  // ignored
    EXPECT_TRUE(withNan.empty());
    for (const Bounds& b : {Bounds{}, withNan}) {
        LightView light = fitLightFrustum(b, {0, -1, 0.2f}, 10.0f, 0);  // map size 0 too
        EXPECT_TRUE(finite(light.viewProjection));
        EXPECT_GT(light.halfWidth, 0.0f);
        EXPECT_TRUE(std::isfinite(light.texelWorldSize));
    }
}

TEST(LightFrustum, CentreIsSnappedToWholeTexels) {
    glm::vec3 dir(-0.8f, -0.35f, -0.45f);
    LightView a = fitLightFrustum(box({-3, 0, -3}, {3, 2, 3}), dir, 4.0f, 256);
    // Moving everything by a tenth of a texel across the light keeps the map where it was.
    glm::vec3 shift = glm::vec3(a.view[0][0], a.view[1][0], a.view[2][0]) * (0.1f * a.texelWorldSize);
    LightView b =
        fitLightFrustum(box(glm::vec3(-3, 0, -3) + shift, glm::vec3(3, 2, 3) + shift), dir, 4.0f, 256);
    glm::vec3 pa = ndc(a, glm::vec3(0.3f, 0.1f, 0.2f));
    glm::vec3 pb = ndc(b, glm::vec3(0.3f, 0.1f, 0.2f));
    EXPECT_NEAR(pa.x, pb.x, 1e-4f);
    EXPECT_NEAR(pa.y, pb.y, 1e-4f);
}

TEST(LightFrustum, StableUpAxisAvoidsTheLightDirection) {
    EXPECT_EQ(stableUpAxis({0, -1, 0}), glm::vec3(0, 0, 1));
    EXPECT_EQ(stableUpAxis({0.6f, -0.8f, 0}), glm::vec3(0, 1, 0));
}
