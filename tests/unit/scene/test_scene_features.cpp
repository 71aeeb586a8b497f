// What a scene calls for, and the reasons given when it does not.
#include <gtest/gtest.h>

#include "scene/scene_features.hpp"
#include "scene/scene_loader.hpp"
#include "scene_test_support.hpp"

namespace {

using fx::SceneFeature;

TEST(SceneFeatures, EveryFieldSceneHasAlmostEverything) {
    auto scene = fx::loadScene(scene_test::dataDir() / "every_field.json", scene_test::testOptions());
    ASSERT_TRUE(scene.ok()) << scene.error();
    fx::SceneFeatures f = fx::features(*scene);
    EXPECT_EQ(f.skinnedMeshes, 1);
    EXPECT_EQ(f.shadowCastingLights, 1);
    EXPECT_EQ(f.particleEmitters, 1);
    EXPECT_EQ(f.cloudLayers, 1);
    EXPECT_EQ(f.hdrEmissiveObjects, 2);  // (8,4,1) x 2.5 and (1,2,8)
    EXPECT_EQ(f.movingObjects, 2);
    EXPECT_EQ(f.lights, 3);
    EXPECT_TRUE(f.physicalLens);
    for (auto feature : {SceneFeature::skinnedMeshes, SceneFeature::shadows, SceneFeature::particles,
                         SceneFeature::clouds, SceneFeature::hdrEmissive, SceneFeature::physicalLens,
                         SceneFeature::movingObjects, SceneFeature::bloom, SceneFeature::colorMatrix,
                         SceneFeature::radialBlur, SceneFeature::depthOfField, SceneFeature::toneMap}) {
        EXPECT_TRUE(f.has(feature)) << static_cast<int>(feature);
        EXPECT_EQ(f.missingReason(feature), "");
    }
    EXPECT_FALSE(f.has(SceneFeature::manyLights));
    EXPECT_EQ(f.missingReason(SceneFeature::manyLights), "scene has 3 lights; many lights means more than 4");
}

TEST(SceneFeatures, EmptySceneSaysWhyForEachFeature) {
    auto scene = fx::loadScene(scene_test::dataDir() / "minimal.json", scene_test::testOptions());
    ASSERT_TRUE(scene.ok()) << scene.error();
    fx::SceneFeatures f = fx::features(*scene);
    EXPECT_EQ(f.missingReason(SceneFeature::particles), "scene has no particle emitter");
    EXPECT_EQ(f.missingReason(SceneFeature::clouds), "scene has no cloud layer");
    EXPECT_EQ(f.missingReason(SceneFeature::shadows), "scene has no light that casts shadows");
    EXPECT_EQ(f.missingReason(SceneFeature::skinnedMeshes),
              "scene has no skinned mesh (no object with a glTF file and an animation clip)");
    EXPECT_EQ(f.missingReason(SceneFeature::hdrEmissive),
              "scene has no HDR emissive object (no emissive colour x strength above 1)");
    EXPECT_EQ(f.missingReason(SceneFeature::physicalLens), "camera has no physical lens (it uses fovY)");
    EXPECT_EQ(f.missingReason(SceneFeature::manyLights), "scene has 0 lights; many lights means more than 4");
    EXPECT_EQ(f.missingReason(SceneFeature::movingObjects), "scene has no moving object");
    EXPECT_EQ(f.missingReason(SceneFeature::bloom), "scene does not ask for bloom (no postEffects.bloom)");
    EXPECT_EQ(f.missingReason(SceneFeature::depthOfField),
              "scene does not ask for depthOfField (no postEffects.depthOfField)");
}

TEST(SceneFeatures, ThresholdsAtTheirEdges) {
    fx::Scene scene;
    // Emissive exactly 1 is not HDR; strength pushes it over.
    fx::SceneObject object;
    object.primitive = fx::Primitive{};
    object.material.emissive = glm::vec3(1.0f, 0.5f, 0.0f);
    scene.objects.push_back(object);
    EXPECT_FALSE(fx::features(scene).has(SceneFeature::hdrEmissive));
    scene.objects[0].material.emissiveStrength = 1.01f;
    EXPECT_TRUE(fx::features(scene).has(SceneFeature::hdrEmissive));

    // Four lights are not many; five are.
    scene.lights.assign(4, fx::Light{});
    EXPECT_FALSE(fx::features(scene).has(SceneFeature::manyLights));
    scene.lights.push_back(fx::Light{});
    EXPECT_TRUE(fx::features(scene).has(SceneFeature::manyLights));

    // A shadow block on a point light casts nothing.
    EXPECT_EQ(fx::features(scene).shadowCastingLights, 0);
    scene.lights[0].type = fx::LightType::point;
    scene.lights[0].shadow.casts = true;
    EXPECT_EQ(fx::features(scene).shadowCastingLights, 0);
    scene.lights[1].shadow.casts = true;
    EXPECT_EQ(fx::features(scene).shadowCastingLights, 1);
}

}  // namespace
