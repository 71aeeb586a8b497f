// The planar reflection's own rules (Deferred rendering chapter's homework, lesson 10 step 7), read back
// as floats on a small scene: a mirror at y = 0 with a box above it, a box below it, and two one-sided
// quads above it (one facing down, one up). Hard case 17: nothing below the plane reaches the
// reflection (the clip plane). Hard case 15: the mirrored view culls front faces, and the pass after it
// (the mirror's surface) culls back faces again. Hard cases 16 and 18: the reflected box is lit by the
// unmirrored sun with its own normals (mirroring the camera, not the objects, leaves both as they are).
// Hard case 14: the reflection lands where the mirror shows it at every reflection_size, also when the
// output's size is not a multiple of the fraction (the reflection keeps the output's aspect).
#include <array>
#include <cmath>
#include <optional>

#include <glm/gtc/matrix_transform.hpp>

#include "effects/deferred/planar_reflection.hpp"
#include "test_deferred_harness.hpp"

using namespace fx;
using namespace fx::test;

namespace {

// The sun shines along (-1, -1, 0): the light comes from +X and above, at 45 degrees.
constexpr float kAmbient = 0.1f;
const glm::vec3 kRed(0.8f, 0.1f, 0.1f);

// The red box stands `redBoxSize` m tall with its bottom half a metre above the mirror.
std::string mirrorSceneJson(float redBoxX, float redBoxSize) {
    return cat(R"({"version": 1, "name": "mirror test", "background": [0.02, 0.02, 0.05],
      "ambient": [0.1, 0.1, 0.1],
      "camera": {"position": [0, 3, 6], "target": [0, 0, -1], "fovY": 60, "near": 0.1, "far": 100},
      "lights": [{"type": "directional", "name": "sun", "direction": [-1, -1, 0], "color": [1, 1, 1],
                  "intensity": 1}],
      "objects": [
        {"name": "mirror", "primitive": {"shape": "plane", "size": [60, 60]},
         "material": {"baseColor": [0, 0, 0]}, "mirror": {"strength": 1}},
        {"name": "red box", "primitive": {"shape": "box", "size": [)",
               redBoxSize, ", ", redBoxSize, ", ", redBoxSize, R"(]},
         "transform": {"position": [)",
               redBoxX, ", ", 0.5f + redBoxSize / 2, R"(, -1]}, "material": {"baseColor": [0.8, 0.1, 0.1]}},
        {"name": "green box below", "primitive": {"shape": "box", "size": [1, 1, 1]},
         "transform": {"position": [1.5, -1, -1]}, "material": {"baseColor": [0.1, 0.8, 0.1]}},
        {"name": "blue quad facing down", "primitive": {"shape": "plane", "size": [1, 1]},
         "transform": {"position": [0, 2, -3], "rotation": [180, 0, 0]},
         "material": {"baseColor": [0.1, 0.1, 0.8]}},
        {"name": "yellow quad facing up", "primitive": {"shape": "plane", "size": [1, 1]},
         "transform": {"position": [2, 2, -3]}, "material": {"baseColor": [0.8, 0.8, 0.1]}}
      ]})");
}

class PlanarReflectionOnGl : public GlTest {
protected:
    void load(float redBoxX = -1.5f, float redBoxSize = 1.0f) {
        auto parsed = parseScene(mirrorSceneJson(redBoxX, redBoxSize), "mirror-test.json");
        ASSERT_TRUE(parsed.ok()) << parsed.error();
        scene = std::move(*parsed);
        meshes.emplace(scene);
        reflection.emplace(scene);
        // One light of radius 0: it adds nothing (the buffer is not empty).
        lights.upload({{glm::vec4(0, 100, 0, 0), glm::vec4(1, 1, 1, 0)}});
        ASSERT_TRUE(programsBuilt());
    }

    struct Frame {
        FloatImage reflected;  // reflection.color
        FloatImage shown;      // deferred.color after the mirror's surface
    };
    Frame render(Size2D size, int fraction, const ReflectionMistakes& mistakes = {},
                 ReflectionBlur blur = {}) {
        GlFrameRunner runner(size);
        Frame f;
        for (bool wantReflection : {true, false}) {
            FloatImage image = runner.frameAndRead([&](FrameGraph& graph) {
                const World world(scene, *meshes, 0.0);
                GBufferTargets g = gbuffer.declare(graph, world, {GBufferLayout::compact, false, {}});
                TextureHandle lit =
                    lighting.declare(graph, scene, g, lights, DeclaredShadowMap{}, std::nullopt);
                TextureHandle color =
                    reflection->declare(graph, world, lights, g, lit, fraction, mistakes, blur);
                return wantReflection ? color : lit;
            });
            (wantReflection ? f.reflected : f.shown) = std::move(image);
        }
        return f;
    }

    // Where world point p lands in an image of `size` seen by the scene's camera, mirrored in y = 0 or
    // not, in texels (x right, y up as GL stores them).
    glm::vec2 projected(glm::vec3 p, Size2D size, bool mirrored) const {
        CameraMatrices c = cameraMatrices(scene.camera, size.width, size.height);
        glm::mat4 view = mirrored ? c.view * reflectionMatrix(glm::vec4(0, 1, 0, 0)) : c.view;
        glm::vec4 clip = c.projection * view * glm::vec4(p, 1.0f);
        glm::vec2 ndc = glm::vec2(clip) / clip.w;
        return (ndc * 0.5f + 0.5f) * glm::vec2(size.width, size.height);
    }

    static glm::vec3 at(const FloatImage& image, glm::vec2 texelPosition) {
        int x = std::clamp(int(texelPosition.x), 0, image.width - 1);
        int y = std::clamp(int(texelPosition.y), 0, image.height - 1);
        return {image.texel(x, y, 0), image.texel(x, y, 1), image.texel(x, y, 2)};
    }

    // Texels whose colour is mostly `channel` (above 0.04 and twice both others).
    static int countDominant(const FloatImage& image, int channel) {
        int n = 0;
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) {
                float v = image.texel(x, y, channel);
                bool dominant = true;
                for (int c = 0; c < 3; ++c)
                    if (c != channel && !(v > 0.04f && v > 2.0f * image.texel(x, y, c))) dominant = false;
                n += dominant;
            }
        return n;
    }

    Scene scene;
    std::optional<SceneMeshes> meshes;  // made for the scene load() reads
    GBufferPass gbuffer;
    DeferredLighting lighting;
    std::optional<PlanarReflection> reflection;  // made for the scene load() reads
    PointLightBuffer lights;
};

}  // namespace

TEST(PlanarReflectionMatrix, MirrorsInThePlaneWithDeterminantMinusOne) {
    glm::mat4 r = reflectionMatrix(glm::vec4(0, 1, 0, -2));  // the plane y = 2
    glm::vec4 p = r * glm::vec4(1, 5, -3, 1);
    EXPECT_FLOAT_EQ(p.x, 1.0f);
    EXPECT_FLOAT_EQ(p.y, -1.0f);
    EXPECT_FLOAT_EQ(p.z, -3.0f);
    EXPECT_FLOAT_EQ(glm::determinant(r), -1.0f);
}

// Hard case 17: the box under the mirror is in front of the mirrored camera, and only the clip plane
// keeps it out of the reflection. The mirror's own plane is clipped too (a millimetre above it).
TEST_F(PlanarReflectionOnGl, TheClipPlaneKeepsEverythingBelowTheMirrorOutOfTheReflection) {
    load();
    const Size2D size{160, 90};
    Frame f = render(size, 1);
    ASSERT_FALSE(f.reflected.empty());
    ASSERT_TRUE(allFinite(f.reflected));
    glm::vec2 below = projected({1.5f, -1.0f, -1.0f}, size, true);
    ASSERT_GT(below.x, 0);
    ASSERT_LT(below.x, size.width);
    ASSERT_GT(below.y, 0);
    ASSERT_LT(below.y, size.height);
    EXPECT_EQ(countDominant(f.reflected, 1), 0) << "green texels: the box below the mirror is reflected";
    EXPECT_NEAR(at(f.reflected, below).g, 0.02f, 1e-3f) << "the sky's colour where the box below would be";
    EXPECT_GT(countDominant(f.reflected, 0), 50);  // the red box above it is there
}

// Hard case 15: mirroring the view turns every triangle's winding round, so the reflection pass culls
// front faces: the quad facing down (towards the mirror) is reflected, the one facing up is not, as in
// a real mirror. The mirror's surface, drawn next, culls back faces again: were the front-face culling
// left on, its upward plane would be culled and the mirror would show nothing.
TEST_F(PlanarReflectionOnGl, TheMirroredViewCullsFrontFacesAndTheNextPassBackFacesAgain) {
    load();
    const Size2D size{160, 90};
    Frame f = render(size, 1);
    ASSERT_FALSE(f.reflected.empty());
    glm::vec2 down = projected({0, 2, -3}, size, true), up = projected({2, 2, -3}, size, true);
    EXPECT_GT(at(f.reflected, down).b, 0.05f) << "the quad facing the mirror is missing from the reflection";
    EXPECT_LT(at(f.reflected, up).r, 0.03f) << "the back of the quad facing up is in the reflection";
    EXPECT_GT(countDominant(f.reflected, 2), 20);
    // On screen: the red box's reflection under the mirror's surface (strength 1: the reflection itself).
    glm::vec2 boxInMirror = projected({-1.0f, -1.0f, -1.0f}, size, false);
    glm::vec3 shown = at(f.shown, boxInMirror), reflected = at(f.reflected, boxInMirror);
    EXPECT_GT(shown.r, 0.3f) << "the mirror's surface is not drawn (front faces still culled?)";
    expectNear(shown, reflected, "the mirror shows its reflection");
}

// Hard cases 16 and 18: the reflected box keeps its normals and the sun keeps its direction. Its face
// towards +X is lit by the sun (n.l = cos 45 deg) and its bottom is not: albedo x (ambient + n.l) and
// albedo x ambient. A mirrored normal matrix (determinant -1) that flips normals, or a sun left
// unmirrored when the objects are mirrored instead of the camera, lights the bottom and darkens the side.
TEST_F(PlanarReflectionOnGl, TheReflectionIsLitByTheSunAsTheBoxIs) {
    load();
    const Size2D size{160, 90};
    Frame f = render(size, 1);
    ASSERT_FALSE(f.reflected.empty());
    glm::vec3 side = at(f.reflected, projected({-0.99f, 1.0f, -1.0f}, size, true));
    glm::vec3 bottom = at(f.reflected, projected({-1.5f, 0.51f, -1.0f}, size, true));
    const float lambert = std::sqrt(0.5f);
    expectNear(side, kRed * (kAmbient + lambert), "the face towards the sun");
    expectNear(bottom, kRed * kAmbient, "the bottom, away from the sun");
}

// Hard cases 16 and 18, the raw-GL alternative (lesson 10's mirror_objects): the objects mirrored
// (model matrix times the reflection, determinant -1) under the unmirrored camera. The box lands where
// it does when the camera is mirrored, but its normals are mirrored and the sun is not: the face away
// from the sun (the bottom, normal -y, mirrored to +y) is lit as if the sun shone from below, and the
// face towards it keeps its light only because the sun's x is not mirrored in y = 0. The winding turns
// round in both (determinant -1): the pass culls front faces either way, and the box is drawn.
TEST_F(PlanarReflectionOnGl, MirroringTheObjectsInsteadLightsTheReflectionFromBelow) {
    load();
    const Size2D size{160, 90};
    Frame camera = render(size, 1);
    Frame objects = render(size, 1, {.mirrorObjects = true, .clearColor = std::nullopt});
    ASSERT_FALSE(camera.reflected.empty() || objects.reflected.empty());
    const glm::vec2 sideAt = projected({-0.99f, 1.0f, -1.0f}, size, true);
    const glm::vec2 bottomAt = projected({-1.5f, 0.51f, -1.0f}, size, true);
    const float lambert = std::sqrt(0.5f);
    expectNear(at(camera.reflected, bottomAt), kRed * kAmbient,
               "mirrored camera: the bottom, away from the sun");
    expectNear(at(objects.reflected, bottomAt), kRed * (kAmbient + lambert),
               "mirrored objects: the bottom, lit from below");
    expectNear(at(objects.reflected, sideAt), at(camera.reflected, sideAt), "the side towards the sun");
    // The same geometry in the same place: as many red texels either way.
    EXPECT_NEAR(countDominant(objects.reflected, 0), countDominant(camera.reflected, 0), 2);
    EXPECT_GT(countDominant(objects.reflected, 0), 20);
}

// The chapter's "background in the reflection": the reflection target is cleared, and wherever nothing
// is reflected the mirror shows strength x the clear colour. fxlab clears it to the scene's sky (a
// mirror there shows the sky); lesson 10's reflection_clear=chapter clears it to the chapter's
// (0.1, 0.2, 0.3), and the mirror (strength 1, black itself) turns that colour where it is empty.
TEST_F(PlanarReflectionOnGl, TheClearColourTintsTheMirrorWhereNothingIsReflected) {
    load();
    const Size2D size{160, 90};
    const glm::vec2 empty = projected({4.0f, 0.0f, 2.0f}, size, false);  // reflects the sky above +X
    Frame sky = render(size, 1);
    Frame tinted = render(size, 1, {.mirrorObjects = false, .clearColor = glm::vec3(0.1f, 0.2f, 0.3f)});
    ASSERT_FALSE(sky.shown.empty() || tinted.shown.empty());
    expectNear(at(sky.shown, empty), glm::vec3(0.02f, 0.02f, 0.05f), "cleared to the sky");
    expectNear(at(tinted.shown, empty), glm::vec3(0.1f, 0.2f, 0.3f), "cleared to the chapter's colour");
    // Where the box is reflected the clear colour is covered.
    const glm::vec2 side = projected({-0.99f, 1.0f, -1.0f}, size, true);
    expectNear(at(tinted.shown, side), at(sky.shown, side), "the box's reflection");
}

// The homework's optional blur, as the chapter's host sets it up: 16 standard-normal samples from
// Xorshift128 through Box-Muller. The generator's first two numbers from Marsaglia's seeds are
// 3701687786 and 458299110 (his published sequence), so the first sample is known independently.
TEST(ReflectionBlurOffsets, AreSixteenStandardNormalSamplesFromXorshift128ThroughBoxMuller) {
    std::array<glm::vec2, 16> samples = reflectionBlurOffsets();
    EXPECT_NEAR(samples[0].x, 0.42723401f, 1e-5f);
    EXPECT_NEAR(samples[0].y, 0.33879379f, 1e-5f);
    EXPECT_EQ(samples, reflectionBlurOffsets()) << "the same samples every run";
    double mean = 0, square = 0;
    for (glm::vec2 s : samples) {
        ASSERT_TRUE(std::isfinite(s.x) && std::isfinite(s.y));
        mean += double(s.x + s.y);
        square += double(s.x * s.x + s.y * s.y);
    }
    // 32 standard-normal numbers: a mean within 3/sqrt(32) of 0, a variance near 1.
    EXPECT_LT(std::abs(mean / 32.0), 0.54);
    EXPECT_GT(square / 32.0, 0.4);
    EXPECT_LT(square / 32.0, 2.0);
}

// With the blur, each mirror pixel shows the average of the 16 bilinear taps of the reflection around
// its own place, at sigma times each sample; with sigma 0 it shows the one sharp tap.
TEST_F(PlanarReflectionOnGl, TheHomeworksBlurAveragesSixteenTapsAroundThePixelsPlace) {
    load();
    const Size2D size{96, 64};
    const float sigma = 0.02f;
    Frame sharp = render(size, 1);
    Frame blurred = render(size, 1, {}, ReflectionBlur{sigma});
    ASSERT_FALSE(sharp.shown.empty() || blurred.shown.empty());
    const std::array<glm::vec2, 16> offsets = reflectionBlurOffsets();
    // The reflection as the sampler reads it: bilinear, texel centres at half-texels.
    auto bilinear = [&](glm::vec2 uv) {
        glm::vec2 p = uv * glm::vec2(size.width, size.height) - 0.5f;
        glm::ivec2 i(glm::floor(p));
        glm::vec2 f = p - glm::vec2(i);
        auto texel = [&](int x, int y) { return at(sharp.reflected, {float(x), float(y)}); };
        return glm::mix(glm::mix(texel(i.x, i.y), texel(i.x + 1, i.y), f.x),
                        glm::mix(texel(i.x, i.y + 1), texel(i.x + 1, i.y + 1), f.x), f.y);
    };
    int checked = 0;
    float largestChange = 0.0f;
    for (int y = 8; y < size.height - 8; ++y)
        for (int x = 8; x < size.width - 8; ++x) {
            glm::vec3 shown = at(sharp.shown, {float(x), float(y)});
            // A mirror pixel with nothing in front: the black mirror at strength 1 shows its reflection.
            if (glm::length(shown - at(sharp.reflected, {float(x), float(y)})) > 1e-3f) continue;
            glm::vec2 uv((float(x) + 0.5f) / float(size.width), (float(y) + 0.5f) / float(size.height));
            glm::vec3 sum(0.0f);
            for (glm::vec2 o : offsets) sum += bilinear(uv + sigma * o);
            glm::vec3 got = at(blurred.shown, {float(x), float(y)});
            expectNear(got, sum / 16.0f, "a blurred mirror pixel");
            largestChange = std::max(largestChange, glm::length(got - shown));
            ++checked;
        }
    EXPECT_GT(checked, 500) << "mirror pixels compared";
    EXPECT_GT(largestChange, 0.05f) << "the blur changed nothing";
    Frame none = render(size, 1, {}, ReflectionBlur{0.0f});
    for (int y = 0; y < size.height; ++y)
        for (int x = 0; x < size.width; ++x)
            ASSERT_EQ(at(none.shown, {float(x), float(y)}), at(sharp.shown, {float(x), float(y)}));
}

// Hard case 14: at every reflection_size the red box's reflection lands where it does at full size
// (the mirror's surface reads the reflection at the pixel's own place as a fraction of the output).
// 256 x 42 is not a multiple of 4: the quarter-size target is 64 x 10, whose own aspect (6.4) is not
// the output's (6.1); a reflection projected with the target's aspect slides sideways.
TEST_F(PlanarReflectionOnGl, TheReflectionRegistersAtEveryReflectionSize) {
    load(-18.0f, 3.0f);
    for (Size2D size : {Size2D{512, 100}, Size2D{256, 42}}) {
        // The centroid of the red reflection (redness r - max(g, b)) under the mirror's horizon.
        auto centroid = [&](const FloatImage& image) {
            const float below = projected({-18.0f, 0.0f, -1.0f}, size, false).y;
            double sx = 0, sy = 0, sw = 0;
            for (int y = 0; y < image.height; ++y)
                for (int x = 0; x < image.width; ++x) {
                    if (float(y) + 0.5f > below) continue;
                    float w = image.texel(x, y, 0) - std::max(image.texel(x, y, 1), image.texel(x, y, 2));
                    if (w <= 0.01f) continue;
                    sx += w * (x + 0.5);
                    sy += w * (y + 0.5);
                    sw += w;
                }
            EXPECT_GT(sw, 1.0) << "no reflection of the red box at " << size.width << "x" << size.height;
            return sw > 0 ? glm::vec2(float(sx / sw), float(sy / sw)) : glm::vec2(-1000);
        };
        Frame full = render(size, 1);
        ASSERT_FALSE(full.shown.empty());
        glm::vec2 reference = centroid(full.shown);
        // At full size it lies inside the picture of the box's mirror image (its corners, projected).
        glm::vec2 low(1e9f), high(-1e9f);
        for (float x : {-19.5f, -16.5f})
            for (float y : {-0.5f, -3.5f})
                for (float z : {-2.5f, 0.5f}) {
                    glm::vec2 p = projected({x, y, z}, size, false);
                    low = glm::min(low, p);
                    high = glm::max(high, p);
                }
        EXPECT_GT(reference.x, low.x);
        EXPECT_LT(reference.x, high.x);
        EXPECT_GT(reference.y, low.y);
        EXPECT_LT(reference.y, high.y);
        for (int fraction : {2, 4}) {
            Frame f = render(size, fraction);
            glm::vec2 got = centroid(f.shown);
            std::printf("%dx%d, 1/%d: the reflection's centroid (%.2f, %.2f), at full size (%.2f, %.2f)\n",
                        size.width, size.height, fraction, got.x, got.y, reference.x, reference.y);
            EXPECT_NEAR(got.x, reference.x, 1.0f) << size.width << "x" << size.height << ", 1/" << fraction;
            EXPECT_NEAR(got.y, reference.y, 1.0f) << size.width << "x" << size.height << ", 1/" << fraction;
        }
    }
}
