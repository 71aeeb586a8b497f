// The cloud pass in a frame: the world position from the depth and the matrices that drew it, the
// jitter averaged over frames, the sun's shadow map under the cloud, and the generated texture far from
// the origin and late in the clock. Read back as floats (test_clouds_harness.hpp).
#include "test_clouds_harness.hpp"

using namespace fx;
using namespace fx::test;

namespace {

TEST_F(CloudsOnGl, TheWorldPositionFromDepthUsesTheMatricesThatDrewIt) {
    // A floor under the eye, its depth written as a camera would: at 0.5 m (under the plane at 1 m)
    // the plane is in front of it; at 1.5 m the floor is in front of the plane and hides it.
    const int w = 16, h = 16;
    Camera cam = cameraAt({0, 6, 0}, 20, -40);
    CloudFrameSettings s = marchSettings(cam, w, h);
    s.stage = CloudStage::plane;
    s.planeHeight = 1.0f;
    s.features = cloudRejectBehind | cloudDepthAware;
    glm::mat4 inverseViewProjection = glm::inverse(s.projection * s.view);
    auto floorDepth = [&](float floorY) {
        std::vector<float> depth(std::size_t(w * h), 1.0f);
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                glm::vec4 ndc((x + 0.5f) / w * 2 - 1, (y + 0.5f) / h * 2 - 1, 1.0f, 1.0f);
                glm::vec4 farPoint = inverseViewProjection * ndc;
                glm::vec3 dir = glm::normalize(glm::vec3(farPoint) / farPoint.w - s.cameraPosition);
                if (dir.y >= 0) continue;
                glm::vec3 hit = s.cameraPosition + dir * ((floorY - s.cameraPosition.y) / dir.y);
                glm::vec4 clip = s.projection * s.view * glm::vec4(hit, 1.0f);
                depth[std::size_t(y * w + x)] = clip.z / clip.w * 0.5f + 0.5f;
            }
        }
        return depth;
    };
    FloatImage below = run(s, w, h, constant, floorDepth(0.5f));
    FloatImage above = run(s, w, h, constant, floorDepth(1.5f));
    ASSERT_TRUE(allFinite(below));
    ASSERT_TRUE(allFinite(above));
    std::vector<float> depthBelow = floorDepth(0.5f);
    int floorPixels = 0;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            if (depthBelow[std::size_t(y * w + x)] >= 1.0f) continue;
            ++floorPixels;
            EXPECT_GT(alphaAt(below, x, y), 0.1f) << x << "," << y;
            EXPECT_EQ(alphaAt(above, x, y), 0.0f) << x << "," << y;
        }
    }
    EXPECT_GT(floorPixels, w * h / 2);
}

TEST_F(CloudsOnGl, AJitterAveragedOverFramesConvergesToManySamples) {
    // A floor inside the slab cuts every ray at another height: with 8 samples its opacity comes in
    // bands. Interleaved gradient noise moves the start every frame; averaged over 16 frames (with
    // reprojection, the camera still) the error against 512 samples falls well below one frame's.
    const int w = 32, h = 24;
    Camera cam = cameraAt({0, 5, 0}, 0, -40);
    CloudFrameSettings s = marchSettings(cam, w, h);
    s.features |= cloudBeerLambert | cloudDistanceOcclusion;
    glm::mat4 inverseViewProjection = glm::inverse(s.projection * s.view);
    std::vector<float> floorDepth(std::size_t(w * h), 1.0f);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            glm::vec4 far =
                inverseViewProjection * glm::vec4((x + 0.5f) / w * 2 - 1, (y + 0.5f) / h * 2 - 1, 1, 1);
            glm::vec3 dir = glm::normalize(glm::vec3(far) / far.w - s.cameraPosition);
            if (dir.y >= 0) continue;
            glm::vec3 hit = s.cameraPosition + dir * ((0.7f - s.cameraPosition.y) / dir.y);
            glm::vec4 clip = s.projection * s.view * glm::vec4(hit, 1.0f);
            floorDepth[std::size_t(y * w + x)] = clip.z / clip.w * 0.5f + 0.5f;
        }
    }
    CloudFrameSettings reference = s;
    reference.march = cloudMarch(0.0f, 2.0f, 512.0f, 0.5f);
    FloatImage truth = run(reference, w, h, constant, floorDepth);

    gl::Texture color = gl::Texture::create2D(TextureFormat::RGBA16F, w, h, 1, "test.scene.color");
    gl::Texture depth = gl::Texture::create2D(TextureFormat::Depth32F, w, h, 1, "test.scene.depth");
    glTextureSubImage2D(depth.name(), 0, 0, 0, w, h, GL_DEPTH_COMPONENT, GL_FLOAT, floorDepth.data());
    CloudTemporal temporal;
    ASSERT_TRUE(programsBuilt());
    auto rmse = [&](const FloatImage& x) {
        double sum = 0;
        for (int j = 0; j < h; ++j)
            for (int i = 0; i < w; ++i) sum += std::pow(double(x.texel(i, j, 3) - truth.texel(i, j, 3)), 2.0);
        return std::sqrt(sum / double(w * h));
    };
    double firstError = 0, lastError = 0;
    GlFrameRunner runner({w, h});  // one pool for the 16 frames, as in the lesson
    for (int frame = 0; frame < 16; ++frame) {
        const float zero[4] = {0, 0, 0, 0};
        glClearTexImage(color.name(), 0, GL_RGBA, GL_FLOAT, zero);
        CloudFrameSettings f = s;
        f.dither = CloudDither::ign;
        f.frameIndex = frame;
        Status status = runner.frame([&](FrameGraph& graph) {
            TextureHandle c = graph.importTexture("scene.color", color.spec(), color.name());
            TextureHandle d = graph.importTexture("scene.depth", depth.spec(), depth.name());
            temporal.declare(graph, pass, {c, d, nullptr}, constant, f, {true, false}, 1u, {w, h});
        });
        ASSERT_TRUE(status) << status.error();
        FloatImage out = gl::readTexture(color);
        ASSERT_TRUE(allFinite(out));
        (frame == 0 ? firstError : lastError) = rmse(out);
    }
    EXPECT_EQ(temporal.framesAveraged(), 16);
    EXPECT_GT(firstError, 0.01);  // one frame of 8 jittered samples is visibly off
    EXPECT_LT(lastError, 0.5 * firstError);
}

TEST_F(CloudsOnGl, TheSunStraightOverheadShadowsTheCloudUnderAPillar) {
    // The lesson's scene with the sun straight down: a look-at with up = +Y would have no sideways axis
    // (hard case 14). Seen from above, rays through the pillar's footprint cross slab samples in its
    // shadow (the depth is left at 1, so the pillar does not hide them); rays beside it do not.
    const int w = 33, h = 33;
    Camera cam = cameraAt({kPillar.x, 12.0f, kPillar.z}, 0, -89.5f);
    CloudFrameSettings s = marchSettings(cam, w, h);
    s.features |= cloudShadows;
    FloatImage out = runUnderTheSun(s, w, h, constant);
    ASSERT_TRUE(allFinite(out));
    // rgb = colour x (1 - shadow) x opacity: rgb / alpha is the light reaching the cloud.
    auto light = [&](int x, int y) { return out.texel(x, y, 0) / std::max(alphaAt(out, x, y), 1e-6f); };
    EXPECT_GT(alphaAt(out, w / 2, h / 2), 0.5f);
    EXPECT_LT(light(w / 2, h / 2), 0.8f);
    EXPECT_GT(light(2, 2), 0.95f);
    EXPECT_GT(light(w - 3, h - 3), 0.95f);
}

TEST_F(CloudsWithTheGeneratedTexture, ACamera10KmFromTheOriginSeesTheSameClouds) {
    // 1/256 and 1/128 repeats per metre: 10.24 km is a whole number of repeats of both layers.
    const int w = 24, h = 16;
    Camera home = cameraAt({0, 5, 0}, 30, -30);
    Camera away = cameraAt({10240.0f, 5, -10240.0f}, 30, -30);
    CloudFrameSettings s0 = marchSettings(home, w, h), s1 = marchSettings(away, w, h);
    s0.scales = s1.scales = {1.0f / 256.0f, 1.0f / 128.0f};
    FloatImage near = run(s0, w, h, texture), far = run(s1, w, h, texture);
    ASSERT_TRUE(allFinite(far));
    // What is left comes from the camera's own matrices (a look-at from a position of 10240 m keeps
    // about 1e-3 m of it), not from the texture coordinates.
    double same = meanAbsoluteAlphaDifference(near, far);
    CloudFrameSettings moved = marchSettings(cameraAt({0.5f, 5, 0}, 30, -30), w, h);
    moved.scales = s0.scales;
    double halfMetre = meanAbsoluteAlphaDifference(near, run(moved, w, h, texture));
    std::printf("10 km: mean |difference| %g, camera moved 0.5 m: %g\n", same, halfMetre);
    EXPECT_LT(same, 2e-3);
    EXPECT_GT(halfMetre, 5.0 * same);  // the comparison sees a camera moved by half a metre
}

TEST_F(CloudsWithTheGeneratedTexture, AClockAt200HoursScrollsAsFarPerSecondAsInTheFirstMinute) {
    // After 200 hours of scrolling, one more second of 60 frames (advanced as the lesson does) must
    // move the clouds by speed x 1 s, exactly as in the first minute: the picture equals the one drawn
    // with the offset moved by that amount in one go. The chapter's unwrapped float stalls there.
    const int w = 48, h = 32;
    const glm::dvec4 start{0.0, 0.0, 0.3, 0.7}, speed{-0.0019, -0.0041, -0.0027, -0.0013};
    Camera cam = cameraAt({0, 5, 0}, 0, -35);
    for (double seconds : {60.0, 200.0 * 3600.0}) {
        CloudScroll scroll = CloudScroll::at(start, speed, seconds);
        CloudFrameSettings s = marchSettings(cam, w, h);
        s.scrollOffset = scroll.offset();
        FloatImage before = run(s, w, h, texture);
        CloudScroll oneStep = scroll;
        oneStep.advance(speed, 1.0);
        for (int i = 0; i < 60; ++i) scroll.advance(speed, 1.0 / 60.0);
        s.scrollOffset = scroll.offset();
        FloatImage framed = run(s, w, h, texture);
        s.scrollOffset = oneStep.offset();
        FloatImage expected = run(s, w, h, texture);
        ASSERT_TRUE(allFinite(framed));
        EXPECT_LT(meanAbsoluteAlphaDifference(framed, expected), 1e-4) << seconds << " s";
        EXPECT_GT(meanAbsoluteAlphaDifference(framed, before), 5e-3) << seconds << " s";  // it moved
    }
}

}  // namespace
