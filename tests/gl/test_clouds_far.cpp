// The cloud pass far away (the Clouds chapter's hard cases 6 and 11): grazing rays from above the slab,
// whose march the chapter caps at 10 x the slab's thickness, and a depth near 1 on distant ground, whose
// world position must not move between two frames. Read back as floats (test_clouds_harness.hpp).
#include <glm/gtc/matrix_inverse.hpp>

#include "test_clouds_harness.hpp"

using namespace fx;
using namespace fx::test;

namespace {

// The ray of pixel (x, y) in world space, from the camera to its far-plane point, as clouds.frag builds
// it for a sky pixel (depth 1), in double.
glm::dvec3 farPointFromCamera(const CloudFrameSettings& s, int x, int y, int w, int h) {
    glm::dvec4 ndc((x + 0.5) / w * 2 - 1, (y + 0.5) / h * 2 - 1, 1.0, 1.0);
    glm::dvec4 view = glm::inverse(glm::dmat4(s.projection)) * ndc;
    return glm::transpose(glm::dmat3(glm::mat3(s.view))) * (glm::dvec3(view) / view.w);
}

TEST_F(CloudsOnGl, GrazingRaysFromAboveMarchOnlyTheTopOfTheSlabAndClipAtTheFarPlane) {
    // Hard case 11. The eye 1 m above the slab (0 to 2 m) looks 4.5 degrees down through a 10-degree
    // field: rays from about sin 9.5 = 0.165 down to level. With |v.y| < 0.1 the step is capped at
    // 10 x 0.25 m, so the 8 samples cross only the top 2 |v.y| / 0.1 m of the slab; with height shaping
    // (0.5 at the top) those rows are thinner than a steep one. Where the far plane (500 m) comes before
    // the slab, the chapter's height test clips the cloud away. Every pixel against the chapter's
    // formulas, and every value finite and in [0, 1].
    const int w = 8, h = 48;
    Camera cam = cameraAt({0, 3, 0}, 0, -4.5f);
    cam.fovYDegrees = 10.0f;
    CloudFrameSettings s = marchSettings(cam, w, h);
    s.features |= cloudHeightShaping;
    FloatImage out = run(s, w, h, constant);
    ASSERT_TRUE(allFinite(out));

    const double top = 2.0, bottom = 0.0, camY = 3.0, stepY = 0.25;
    int grazing = 0, steep = 0, clipped = 0;
    float steepOpacity = 0.0f, thinnestGrazing = 1.0f;
    for (int y = 0; y < h; ++y) {
        glm::dvec3 far = farPointFromCamera(s, 0, y, w, h);
        glm::dvec3 v = glm::normalize(far);
        double rangeMin = std::max(camY + far.y, bottom);  // the far-plane point's height (sky pixel)
        double transmitted = 1.0;
        bool ambiguous = false;
        if (v.y < -1e-7) {
            for (int i = 0; i < 8; ++i) {
                double sampleY = top - i * stepY * (-v.y) / std::max(-v.y, 0.1);
                if (std::abs(sampleY - rangeMin) < 1e-3) ambiguous = true;
                if (sampleY < rangeMin) continue;
                double shaped = a * (std::clamp((top - sampleY) / (top - bottom), 0.0, 1.0) * 0.5 + 0.5);
                transmitted *= 1.0 - std::min(0.3 * shaped, 1.0);
            }
        }
        if (ambiguous) continue;
        const float expected = float(1.0 - transmitted);
        for (int x = 0; x < w; ++x) {
            float alpha = alphaAt(out, x, y);
            EXPECT_NEAR(alpha, expected, kTolerance) << "row " << y << ", v.y " << v.y;
            EXPECT_GE(alpha, 0.0f);
            EXPECT_LE(alpha, 1.0f);
        }
        float alpha = alphaAt(out, w / 2, y);
        if (v.y < 0 && -v.y >= 0.1) {
            ++steep;
            steepOpacity = alpha;
        } else if (v.y < 0 && camY + far.y < bottom) {
            ++grazing;
            thinnestGrazing = std::min(thinnestGrazing, alpha);
        } else if (v.y < 0 && camY + far.y > top) {
            ++clipped;
            EXPECT_EQ(alpha, 0.0f) << "row " << y << ": the slab lies beyond the far plane";
        }
    }
    EXPECT_GT(steep, 0);
    EXPECT_GT(grazing, 4);
    EXPECT_GT(clipped, 0);
    EXPECT_LT(thinnestGrazing, steepOpacity - 0.1f) << "grazing rows cross only the top of the slab";
}

TEST_F(CloudsOnGl, DistantGroundAtDepthNearOneKeepsItsHeightToACentimetreOverTwoFrames) {
    // Hard case 6. Ground at y = 0 seen from 6 m up, level, out to the far plane at 1000 m: its depth
    // runs to 0.9999 and beyond, where a [0, 1] depth buffer has its least precision. Written as a
    // perfect Depth32F buffer would hold it (computed in double, stored as float), in two frames with
    // the camera 1 mm apart (a sub-pixel move). The one-plane stage probes the height the pass
    // reconstructs: a plane 1 cm above the ground is in front of it at every ground pixel, 1 cm below
    // behind it. So a distant occlusion edge stays put within 1 cm from frame to frame: no flicker.
    const int w = 16, h = 64;
    const double delta = 0.01;
    int farPixels = 0;
    std::vector<FloatImage> above, below;
    std::vector<std::vector<float>> depths;
    for (float shift : {0.0f, 0.001f}) {
        Camera cam = cameraAt({shift, 6, 0}, 0, 0);
        cam.fovYDegrees = 4.0f;  // a long lens: several rows between 500 m and the far plane
        cam.far = 1000.0f;
        CloudFrameSettings s = marchSettings(cam, w, h);
        s.stage = CloudStage::plane;
        s.features = cloudRejectBehind | cloudDepthAware;
        const glm::dmat4 viewProjection = glm::dmat4(s.projection) * glm::dmat4(s.view);
        const glm::dmat4 inverse = glm::inverse(viewProjection);
        std::vector<float> depth(std::size_t(w * h), 1.0f);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                glm::dvec4 farPoint =
                    inverse * glm::dvec4((x + 0.5) / w * 2 - 1, (y + 0.5) / h * 2 - 1, 1, 1);
                glm::dvec3 eye(cam.position);
                glm::dvec3 dir = glm::normalize(glm::dvec3(farPoint) / farPoint.w - eye);
                if (dir.y >= 0) continue;
                glm::dvec4 clip = viewProjection * glm::dvec4(eye + dir * (-eye.y / dir.y), 1.0);
                double d = clip.z / clip.w * 0.5 + 0.5;
                if (d >= 1.0) continue;  // beyond the far plane: sky
                depth[std::size_t(y * w + x)] = float(d);
                if (shift == 0.0f && d > 0.9999) ++farPixels;
            }
        s.planeHeight = float(delta);
        above.push_back(run(s, w, h, constant, depth));
        s.planeHeight = float(-delta);
        below.push_back(run(s, w, h, constant, depth));
        depths.push_back(depth);
    }
    EXPECT_GT(farPixels, w * 3) << "too few ground pixels with a depth above 0.9999";
    for (std::size_t frame = 0; frame < 2; ++frame) {
        ASSERT_TRUE(allFinite(above[frame]) && allFinite(below[frame]));
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                float d = depths[frame][std::size_t(y * w + x)];
                if (d >= 1.0f) continue;
                EXPECT_GT(alphaAt(above[frame], x, y), 0.5f)
                    << "frame " << frame << ", pixel " << x << "," << y << ", depth " << d
                    << ": the ground reconstructed more than 1 cm too high";
                EXPECT_EQ(alphaAt(below[frame], x, y), 0.0f)
                    << "frame " << frame << ", pixel " << x << "," << y << ", depth " << d
                    << ": the ground reconstructed more than 1 cm too low";
            }
    }
}

}  // namespace
