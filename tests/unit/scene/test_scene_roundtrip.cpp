// Every field is read, and a scene survives save and load unchanged.
#include <gtest/gtest.h>

#include <limits>

#include "scene/scene_loader.hpp"
#include "scene/scene_writer.hpp"
#include "scene_test_support.hpp"

namespace {

namespace fs = std::filesystem;

fx::Scene loadEveryField() {
    auto scene = fx::loadScene(scene_test::dataDir() / "every_field.json", scene_test::testOptions());
    EXPECT_TRUE(scene.ok()) << (scene.ok() ? "" : scene.error());
    return scene.ok() ? *scene : fx::Scene{};
}

fx::Scene reload(const fx::Scene& scene) {
    std::string text = fx::saveScene(scene);
    auto again = fx::parseScene(text, scene.file, scene_test::testOptions());
    EXPECT_TRUE(again.ok()) << (again.ok() ? "" : again.error()) << "\n" << text;
    if (!again.ok()) return {};
    EXPECT_TRUE(again->warnings.empty()) << "saved text makes warnings:\n" << text;
    return *again;
}

// The fixture sets every field to something other than its default, so a field the loader skipped
// would show here even if the writer skipped it too.
TEST(SceneRoundTrip, EveryFieldIsRead) {
    fx::Scene s = loadEveryField();
    EXPECT_EQ(s.name, "Every field");
    EXPECT_FALSE(s.description.empty());
    EXPECT_EQ(s.background, glm::vec3(0.1f, 0.2f, 0.4f));
    EXPECT_EQ(s.ambient, glm::vec3(0.05f, 0.06f, 0.07f));
    EXPECT_EQ(s.file, scene_test::dataDir() / "every_field.json");

    const fx::Camera& c = s.camera;
    EXPECT_EQ(c.position, glm::vec3(1, 3, 9));
    EXPECT_EQ(c.aim, fx::CameraAim::target);
    EXPECT_EQ(c.target, glm::vec3(0, 1, -0.5f));
    ASSERT_TRUE(c.lens.has_value());
    EXPECT_EQ(*c.lens, (fx::Lens{35.0f, 24.0f, 1.4f, 7.5f}));
    EXPECT_EQ(c.near, 0.05f);
    EXPECT_EQ(c.far, 300.0f);

    ASSERT_EQ(s.lights.size(), 3u);
    const fx::Light& sun = s.lights[0];
    EXPECT_EQ(sun.type, fx::LightType::directional);
    EXPECT_EQ(sun.name, "sun");
    EXPECT_EQ(sun.color, glm::vec3(1, 0.9f, 0.8f));
    EXPECT_EQ(sun.intensity, 3.5f);
    EXPECT_EQ(sun.direction, glm::vec3(-0.4f, -1, -0.3f));
    EXPECT_EQ(sun.shadow, (fx::ShadowSettings{true, 4096, 0.001f, 1.5f, 9, 25.0f}));
    EXPECT_TRUE(sun.castsShadows());
    const fx::Light& lamp = s.lights[1];
    EXPECT_EQ(lamp.type, fx::LightType::point);
    EXPECT_EQ(lamp.position, glm::vec3(2, 1.5f, 0));
    EXPECT_EQ(lamp.radius, 6.0f);
    EXPECT_EQ(lamp.intensity, 12.0f);
    const fx::Light& torch = s.lights[2];
    EXPECT_EQ(torch.type, fx::LightType::spot);
    EXPECT_EQ(torch.direction, glm::vec3(0.5f, -1, -0.2f));
    EXPECT_EQ(torch.radius, 15.0f);
    EXPECT_EQ(torch.innerConeDegrees, 12.0f);
    EXPECT_EQ(torch.outerConeDegrees, 22.0f);

    ASSERT_EQ(s.objects.size(), 6u);
    const fx::SceneObject& ground = s.objects[0];
    ASSERT_TRUE(ground.primitive.has_value());
    EXPECT_EQ(ground.primitive->shape, fx::PrimitiveShape::plane);
    EXPECT_EQ(ground.primitive->planeSize, glm::vec2(40, 30));
    EXPECT_FALSE(ground.castsShadows);
    EXPECT_TRUE(ground.receivesShadows);
    EXPECT_EQ(ground.material.baseColorTexture.path, "assets/crate.png");
    EXPECT_EQ(ground.material.baseColorTexture.resolved,
              fs::weakly_canonical(scene_test::dataDir() / "assets/crate.png"));
    const fx::SceneObject& crate = s.objects[1];
    EXPECT_EQ(crate.primitive->boxSize, glm::vec3(1, 2, 0.5f));
    EXPECT_EQ(crate.transform, (fx::Transform{{3, 1, -2}, {0, 30, 5}, {1.5f, 1, 1.25f}}));
    EXPECT_EQ(crate.material.baseColor, glm::vec3(0.7f, 0.5f, 0.3f));
    EXPECT_FALSE(crate.receivesShadows);
    const fx::SceneObject& ball = s.objects[2];
    EXPECT_EQ(ball.primitive->radius, 0.75f);
    EXPECT_EQ(ball.material.emissive, glm::vec3(8, 4, 1));
    EXPECT_EQ(ball.material.emissiveStrength, 2.5f);
    EXPECT_EQ(ball.motion, (fx::Motion{fx::MotionType::circle, 2.5f, 0.25f, 6.0f, 90.0f}));
    const fx::SceneObject& pillar = s.objects[3];
    EXPECT_EQ(pillar.primitive->shape, fx::PrimitiveShape::cylinder);
    EXPECT_EQ(pillar.primitive->radius, 0.3f);
    EXPECT_EQ(pillar.primitive->height, 4.0f);
    const fx::SceneObject& pill = s.objects[4];
    EXPECT_EQ(pill.primitive->shape, fx::PrimitiveShape::capsule);
    EXPECT_EQ(pill.motion, (fx::Motion{fx::MotionType::bob, 1.0f, 0.6f, 2.0f, -45.0f}));
    const fx::SceneObject& robot = s.objects[5];
    EXPECT_FALSE(robot.primitive.has_value());
    EXPECT_EQ(robot.gltf.path, "assets/robot.gltf");
    EXPECT_EQ(robot.animation, (fx::Animation{{"walk"}, 1.25f}));
    EXPECT_TRUE(robot.skinned);
    EXPECT_EQ(robot.transform.scale, glm::vec3(0.9f));

    ASSERT_EQ(s.emitters.size(), 1u);
    const fx::ParticleEmitter& fire = s.emitters[0];
    EXPECT_EQ(fire.name, "campfire");
    EXPECT_EQ(fire.position, glm::vec3(-2, 0.7f, -4));
    EXPECT_EQ(fire.ratePerSecond, 20.0f);
    EXPECT_EQ(fire.lifetimeSeconds, 1.5f);
    EXPECT_EQ(fire.startSize, 0.6f);
    EXPECT_EQ(fire.endSize, 0.05f);
    EXPECT_EQ(fire.startColor, glm::vec4(6, 2.5f, 0.5f, 0.9f));
    EXPECT_EQ(fire.endColor, glm::vec4(0.8f, 0.1f, 0.02f, 0.1f));
    EXPECT_EQ(fire.riseSpeed, 1.2f);
    EXPECT_EQ(fire.spinDegreesPerSecond, 120.0f);
    EXPECT_EQ(fire.spread, 0.25f);
    EXPECT_EQ(fire.sprite.path, "assets/fire.png");
    EXPECT_EQ(fire.seed, 42);

    ASSERT_EQ(s.clouds.size(), 1u);
    const fx::CloudLayer& cloud = s.clouds[0];
    EXPECT_EQ(cloud.name, "stratus");
    EXPECT_EQ(cloud.bottom, 40.0f);
    EXPECT_EQ(cloud.top, 55.0f);
    EXPECT_EQ(cloud.densityTexture.path, "assets/cloud_density.png");
    EXPECT_EQ(cloud.noise[0], (fx::CloudNoise{0.02f, {0.01f, -0.005f}}));
    EXPECT_EQ(cloud.noise[1], (fx::CloudNoise{0.07f, {-0.003f, 0.002f}}));
    EXPECT_EQ(cloud.threshold, 0.35f);
    EXPECT_EQ(cloud.steps, 24);
    EXPECT_EQ(cloud.color, glm::vec3(1.2f, 1.1f, 1.0f));

    const fx::PostEffects& post = s.postEffects;
    EXPECT_EQ(post.bloom, (fx::BloomSettings{1.2f, 0.3f, 0.8f, 7}));
    EXPECT_EQ(post.colorMatrix, (fx::ColorMatrixSettings{fx::ColorMatrixPreset::sepia, 0.75f}));
    EXPECT_EQ(post.radialBlur, (fx::RadialBlurSettings{{0.4f, 0.6f}, 0.05f, 0.3f, 12}));
    EXPECT_EQ(post.depthOfField, (fx::DepthOfFieldSettings{24.0f, 32}));
    EXPECT_EQ(post.toneMap, (fx::ToneMapSettings{fx::ToneCurve::reinhard, 1.5f}));
}

TEST(SceneRoundTrip, EveryFieldSurvivesSaveAndLoad) {
    fx::Scene original = loadEveryField();
    fx::Scene again = reload(original);
    EXPECT_TRUE(again == original) << fx::saveScene(original);
    // Saving is stable too: the text of the reloaded scene is the same.
    EXPECT_EQ(fx::saveScene(again), fx::saveScene(original));
}

TEST(SceneRoundTrip, YawPitchCameraAndDefaults) {
    fx::Scene scene = loadEveryField();
    scene.camera.aim = fx::CameraAim::yawPitch;
    scene.camera.target = glm::vec3(0.0f);  // not written for a yaw/pitch camera
    scene.camera.yawDegrees = -37.5f;
    scene.camera.pitchDegrees = 12.25f;
    scene.camera.lens.reset();
    scene.camera.fovYDegrees = 47.0f;
    scene.postEffects.depthOfField.reset();
    scene.objects[2].motion = fx::Motion{};
    scene.emitters.clear();
    fx::Scene again = reload(scene);
    EXPECT_TRUE(again == scene) << fx::saveScene(scene);
}

TEST(SceneRoundTrip, ShortestNumbersInTheText) {
    std::string text = fx::saveScene(loadEveryField());
    EXPECT_NE(text.find("\"near\": 0.05,"), std::string::npos) << text;
    EXPECT_NE(text.find("\"emissive\": [8, 4, 1]"), std::string::npos) << text;
    EXPECT_EQ(text.find("0.0500000"), std::string::npos) << text;
}

// A lens focused at a far mountain: JSON has no number for infinity, so the file writes the word.
TEST(SceneRoundTrip, FocusAtInfinityIsWrittenAsTheWord) {
    fx::Scene scene = loadEveryField();
    ASSERT_TRUE(scene.camera.lens.has_value());
    scene.camera.lens->focusDistanceM = std::numeric_limits<float>::infinity();
    std::string text = fx::saveScene(scene);
    EXPECT_NE(text.find("\"focusDistance\": \"infinity\""), std::string::npos) << text;
    fx::Scene again = reload(scene);
    EXPECT_TRUE(again == scene) << text;
}

TEST(SceneRoundTrip, ChangedFieldBreaksEquality) {
    fx::Scene a = loadEveryField();
    fx::Scene b = a;
    EXPECT_TRUE(a == b);
    b.clouds[0].noise[1].scroll.y += 0.001f;
    EXPECT_FALSE(a == b);
}

}  // namespace
