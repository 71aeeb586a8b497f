// Every way the loader refuses a scene: each case breaks one field of a valid scene and checks that the
// message names the file, the field's JSON path and the reason.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/scene_loader.hpp"
#include "scene_test_support.hpp"

namespace {

using nlohmann::json;
using scene_test::contains;

struct BadField {
    const char* name;              // test name
    const char* patch;             // RFC 6902 JSON patch applied to every_field.json
    const char* path;              // JSON path the message must name
    std::vector<const char*> why;  // fragments of the reason
};

// A file that does not exist, in the fixtures' folder, so that relative asset paths still resolve.
std::filesystem::path nominalFile() {
    return scene_test::dataDir() / "patched_every_field.json";
}

void expectRefused(const std::string& text, const std::string& path, const std::vector<const char*>& why) {
    auto scene = fx::parseScene(text, nominalFile(), scene_test::testOptions());
    ASSERT_FALSE(scene.ok()) << "accepted a scene that should fail at " << path;
    const std::string& message = scene.error();
    EXPECT_TRUE(contains(message, nominalFile().string() + ": ")) << message;
    EXPECT_TRUE(contains(message, ": " + path + ": ")) << "expected path " << path << " in: " << message;
    for (const char* fragment : why)
        EXPECT_TRUE(contains(message, fragment)) << "missing \"" << fragment << "\" in: " << message;
}

class SceneErrors : public ::testing::TestWithParam<BadField> {};

TEST_P(SceneErrors, NamesFilePathAndReason) {
    const BadField& bad = GetParam();
    json base = json::parse(scene_test::readFixture("every_field.json"));
    ASSERT_TRUE(fx::parseScene(base.dump(), nominalFile(), scene_test::testOptions()).ok());
    json patched = base.patch(json::parse(bad.patch));
    expectRefused(patched.dump(2), bad.path, bad.why);
}

const BadField kBadFields[] = {
    // Types and presence.
    {"WrongType",
     R"([{"op":"replace","path":"/camera/near","value":"0.1"}])",
     "camera.near",
     {"expected a number, got a string"}},
    {"NullValue", R"([{"op":"replace","path":"/camera/far","value":null}])", "camera.far", {"got null"}},
    {"WrongBoolean",
     R"([{"op":"replace","path":"/objects/0/castsShadows","value":"yes"}])",
     "objects[0].castsShadows",
     {"expected true or false, got a string"}},
    {"NotAnInteger",
     R"([{"op":"replace","path":"/lights/0/shadow/filterTaps","value":2.5}])",
     "lights[0].shadow.filterTaps",
     {"expected an integer, got 2.5"}},
    {"MissingCamera", R"([{"op":"remove","path":"/camera"}])", "camera", {"missing required field"}},
    {"MissingPosition",
     R"([{"op":"remove","path":"/camera/position"}])",
     "camera.position",
     {"missing required field"}},
    {"MissingLightType",
     R"([{"op":"remove","path":"/lights/1/type"}])",
     "lights[1].type",
     {"missing required field"}},
    {"MissingCloudTexture",
     R"([{"op":"remove","path":"/clouds/0/densityTexture"}])",
     "clouds[0].densityTexture",
     {"missing required field"}},
    {"ObjectsNotArray",
     R"([{"op":"replace","path":"/objects","value":{}}])",
     "objects",
     {"expected an array, got an object"}},
    {"ObjectNotObject",
     R"([{"op":"replace","path":"/objects/0","value":5}])",
     "objects[0]",
     {"expected an object, got a number"}},
    {"EmptyName", R"([{"op":"replace","path":"/name","value":""}])", "name", {"empty"}},
    {"FutureVersion",
     R"([{"op":"replace","path":"/version","value":2}])",
     "version",
     {"unsupported format version 2", "version 1"}},
    // Vectors.
    {"VectorTooShort",
     R"([{"op":"replace","path":"/objects/2/material/emissive","value":[8,4]}])",
     "objects[2].material.emissive",
     {"expected 3 numbers, got 2"}},
    {"VectorNotArray",
     R"([{"op":"replace","path":"/camera/position","value":5}])",
     "camera.position",
     {"expected an array of 3 numbers, got a number"}},
    {"VectorElementType",
     R"([{"op":"replace","path":"/objects/2/material/emissive/1","value":"4"}])",
     "objects[2].material.emissive[1]",
     {"expected a number, got a string"}},
    {"NegativeEmissive",
     R"([{"op":"replace","path":"/objects/2/material/emissive/0","value":-1}])",
     "objects[2].material.emissive[0]",
     {"-1 is out of range [0, 10000]"}},
    {"BaseColorAboveOne",
     R"([{"op":"replace","path":"/objects/0/material/baseColor/0","value":1.5}])",
     "objects[0].material.baseColor[0]",
     {"1.5 is out of range [0, 1]"}},
    {"ZeroScale",
     R"([{"op":"replace","path":"/objects/1/transform/scale/0","value":0}])",
     "objects[1].transform.scale[0]",
     {"0 is out of range (0, 10000]"}},
    // Camera.
    {"NearZero",
     R"([{"op":"replace","path":"/camera/near","value":0}])",
     "camera.near",
     {"out of range (0, 10000]"}},
    {"NearNegative",
     R"([{"op":"replace","path":"/camera/near","value":-1}])",
     "camera.near",
     {"out of range (0, 10000]"}},
    {"NearEqualsFar",
     R"([{"op":"replace","path":"/camera/near","value":300}])",
     "camera.far",
     {"300 is not greater than near (300)"}},
    {"NearBeyondFar",
     R"([{"op":"replace","path":"/camera/far","value":0.01}])",
     "camera.far",
     {"not greater than near (0.05)"}},
    {"FovTooWide",
     R"([{"op":"remove","path":"/camera/lens"},{"op":"remove","path":"/postEffects/depthOfField"},
         {"op":"add","path":"/camera/fovY","value":180}])",
     "camera.fovY",
     {"180 is out of range (0, 180)"}},
    {"FovZero",
     R"([{"op":"remove","path":"/camera/lens"},{"op":"remove","path":"/postEffects/depthOfField"},
         {"op":"add","path":"/camera/fovY","value":0}])",
     "camera.fovY",
     {"0 is out of range (0, 180)"}},
    // Values that pass as a double but not as the float the program uses.
    {"ScaleUnderflowsInFloat",
     R"([{"op":"replace","path":"/objects/1/transform/scale/0","value":1e-300}])",
     "objects[1].transform.scale[0]",
     {"becomes 0 as a float", "out of range (0, 10000]"}},
    {"RadiusUnderflowsInFloat",
     R"([{"op":"replace","path":"/objects/2/primitive/radius","value":1e-300}])",
     "objects[2].primitive.radius",
     {"becomes 0 as a float"}},
    {"SizeUnderflowsInFloat",
     R"([{"op":"replace","path":"/objects/0/primitive/size/1","value":1e-300}])",
     "objects[0].primitive.size[1]",
     {"becomes 0 as a float"}},
    {"NearUnderflowsInFloat",
     R"([{"op":"replace","path":"/camera/near","value":1e-300}])",
     "camera.near",
     {"becomes 0 as a float"}},
    {"FocalLengthUnderflowsInFloat",
     R"([{"op":"replace","path":"/camera/lens/focalLength","value":1e-300}])",
     "camera.lens.focalLength",
     {"becomes 0 as a float"}},
    {"SensorWidthUnderflowsInFloat",
     R"([{"op":"replace","path":"/camera/lens/sensorWidth","value":1e-300}])",
     "camera.lens.sensorWidth",
     {"becomes 0 as a float"}},
    {"FovRoundsUpTo180InFloat",
     R"([{"op":"remove","path":"/camera/lens"},{"op":"remove","path":"/postEffects/depthOfField"},
         {"op":"add","path":"/camera/fovY","value":179.99999999}])",
     "camera.fovY",
     {"becomes 180 as a float", "out of range (0, 180)"}},
    {"FovAndLens",
     R"([{"op":"add","path":"/camera/fovY","value":40}])",
     "camera.fovY",
     {"either fovY or lens, not both"}},
    {"FocalLengthZero",
     R"([{"op":"replace","path":"/camera/lens/focalLength","value":0}])",
     "camera.lens.focalLength",
     {"0 is out of range (0, 2000]"}},
    {"FNumberZero",
     R"([{"op":"replace","path":"/camera/lens/fNumber","value":0}])",
     "camera.lens.fNumber",
     {"0 is out of range (0, 64]"}},
    {"FNumberNegative",
     R"([{"op":"replace","path":"/camera/lens/fNumber","value":-2}])",
     "camera.lens.fNumber",
     {"out of range (0, 64]"}},
    {"FocusAtFocalLength",
     R"([{"op":"replace","path":"/camera/lens/focusDistance","value":0.035}])",
     "camera.lens.focusDistance",
     {"0.035 m is not beyond the focal length (35 mm)", "divides by (focus distance - focal length)"}},
    {"FocusJustOutsideFocalLength",
     R"([{"op":"replace","path":"/camera/lens/focusDistance","value":0.03501}])",
     "camera.lens.focusDistance",
     {"not beyond the focal length (35 mm)"}},
    {"FocusInsideFocalLength",
     R"([{"op":"replace","path":"/camera/lens/focusDistance","value":0.01}])",
     "camera.lens.focusDistance",
     {"not beyond the focal length", "focus farther than 0.035035 m"}},
    {"FocusMissing",
     R"([{"op":"remove","path":"/camera/lens/focusDistance"}])",
     "camera.lens.focusDistance",
     {"missing required field"}},
    {"TargetOnCamera",
     R"([{"op":"replace","path":"/camera/target","value":[1,3,9]}])",
     "camera.target",
     {"equals the camera position"}},
    {"TargetStraightDown",
     R"([{"op":"replace","path":"/camera/target","value":[1,0,9]}])",
     "camera.target",
     {"straight above or below"}},
    {"NoAim",
     R"([{"op":"remove","path":"/camera/target"}])",
     "camera.target",
     {"missing required field (give target, or yaw and pitch)"}},
    {"TargetAndYaw",
     R"([{"op":"add","path":"/camera/yaw","value":10}])",
     "camera.yaw",
     {"either target or yaw and pitch, not both"}},
    {"PitchVertical",
     R"([{"op":"remove","path":"/camera/target"},{"op":"add","path":"/camera/yaw","value":0},
         {"op":"add","path":"/camera/pitch","value":90}])",
     "camera.pitch",
     {"90 is out of range (-90, 90)"}},
    {"YawWithoutPitch",
     R"([{"op":"remove","path":"/camera/target"},{"op":"add","path":"/camera/yaw","value":0}])",
     "camera.pitch",
     {"missing required field"}},
    // Lights.
    {"UnknownLightType",
     R"([{"op":"replace","path":"/lights/0/type","value":"sun"}])",
     "lights[0].type",
     {"unknown value \"sun\"", "allowed: directional, point, spot"}},
    {"ZeroDirection",
     R"([{"op":"replace","path":"/lights/0/direction","value":[0,0,0]}])",
     "lights[0].direction",
     {"zero length"}},
    {"InnerConeWider",
     R"([{"op":"replace","path":"/lights/2/innerCone","value":30}])",
     "lights[2].innerCone",
     {"30 is wider than outerCone (22)"}},
    {"OuterConeTooWide",
     R"([{"op":"replace","path":"/lights/2/outerCone","value":90}])",
     "lights[2].outerCone",
     {"out of range (0, 89]"}},
    {"ShadowMapNotPowerOfTwo",
     R"([{"op":"replace","path":"/lights/0/shadow/mapSize","value":1000}])",
     "lights[0].shadow.mapSize",
     {"not a power of two"}},
    {"ShadowMapTooSmall",
     R"([{"op":"replace","path":"/lights/0/shadow/mapSize","value":64}])",
     "lights[0].shadow.mapSize",
     {"64 is out of range [128, 8192]"}},
    {"FilterTapsZero",
     R"([{"op":"replace","path":"/lights/0/shadow/filterTaps","value":0}])",
     "lights[0].shadow.filterTaps",
     {"out of range [1, 64]"}},
    {"NegativeIntensity",
     R"([{"op":"replace","path":"/lights/1/intensity","value":-3}])",
     "lights[1].intensity",
     {"out of range [0, 100000]"}},
    {"PointRadiusZero",
     R"([{"op":"replace","path":"/lights/1/radius","value":0}])",
     "lights[1].radius",
     {"out of range (0, 10000]"}},
    // Objects.
    {"UnknownShape",
     R"([{"op":"replace","path":"/objects/1/primitive/shape","value":"bx"}])",
     "objects[1].primitive.shape",
     {"unknown value \"bx\"", "did you mean \"box\"", "allowed: plane, box, sphere, cylinder, capsule"}},
    {"PlaneSizeOfThree",
     R"([{"op":"replace","path":"/objects/0/primitive/size","value":[1,2,3]}])",
     "objects[0].primitive.size",
     {"expected 2 numbers, got 3"}},
    {"CapsuleTooShort",
     R"([{"op":"replace","path":"/objects/4/primitive/height","value":0.5}])",
     "objects[4].primitive.height",
     {"less than the diameter of the caps"}},
    {"PrimitiveAndGltf",
     R"([{"op":"add","path":"/objects/0/gltf","value":"assets/robot.gltf"}])",
     "objects[0].gltf",
     {"not both"}},
    {"NeitherPrimitiveNorGltf",
     R"([{"op":"remove","path":"/objects/3/primitive"}])",
     "objects[3]",
     {"give \"primitive\" or \"gltf\""}},
    {"AnimationOnPrimitive",
     R"([{"op":"add","path":"/objects/1/animation","value":{"clip":"walk"}}])",
     "objects[1].animation",
     {"only glTF models"}},
    {"EmptyClip",
     R"([{"op":"replace","path":"/objects/5/animation/clip","value":""}])",
     "objects[5].animation.clip",
     {"empty"}},
    {"UnknownMotion",
     R"([{"op":"replace","path":"/objects/2/motion/type","value":"orbit"}])",
     "objects[2].motion.type",
     {"unknown value \"orbit\"", "allowed: none, circle, bob"}},
    {"MotionPeriodZero",
     R"([{"op":"replace","path":"/objects/2/motion/period","value":0}])",
     "objects[2].motion.period",
     {"out of range (0, 3600]"}},
    // Paths.
    {"PathEscapes",
     R"([{"op":"replace","path":"/objects/1/material/baseColorTexture",
          "value":"../../../../../../../../../etc/passwd"}])",
     "objects[1].material.baseColorTexture",
     {"resolves to /etc/passwd", "outside the asset root"}},
    {"AbsolutePathOutside",
     R"([{"op":"replace","path":"/objects/5/gltf","value":"/etc/passwd"}])",
     "objects[5].gltf",
     {"outside the asset root"}},
    {"EmptyPath",
     R"([{"op":"replace","path":"/emitters/0/sprite","value":""}])",
     "emitters[0].sprite",
     {"the path is empty"}},
    {"MissingFile",
     R"([{"op":"replace","path":"/emitters/0/sprite","value":"assets/nope.png"}])",
     "emitters[0].sprite",
     {"file not found: ", "scenes/assets/nope.png", "written as \"assets/nope.png\""}},
    {"MissingGltf",
     R"([{"op":"replace","path":"/objects/5/gltf","value":"assets/robot_v2.gltf"}])",
     "objects[5].gltf",
     {"file not found: ", "scenes/assets/robot_v2.gltf", "written as \"assets/robot_v2.gltf\""}},
    // Models and their clips, read when the scene loads.
    {"ModelDoesNotLoad",
     R"([{"op":"replace","path":"/objects/5/gltf","value":"assets/broken.gltf"}])",
     "objects[5].gltf",
     {"cannot load the model: ", "scenes/assets/broken.gltf: "}},
    {"UnknownClip",
     R"([{"op":"replace","path":"/objects/5/animation/clip","value":"wlak"}])",
     "objects[5].animation.clip",
     {"assets/robot.gltf has no clip \"wlak\" (did you mean \"walk\"?); its clips: walk, wave"}},
    {"UnknownClipInAList",
     R"([{"op":"replace","path":"/objects/5/animation/clip","value":["walk", "jump"]}])",
     "objects[5].animation.clip",
     {"has no clip \"jump\"", "its clips: walk, wave"}},
    {"ClipListEmpty",
     R"([{"op":"replace","path":"/objects/5/animation/clip","value":[]}])",
     "objects[5].animation.clip",
     {"the list of clips is empty"}},
    {"ClipListWithStar",
     R"([{"op":"replace","path":"/objects/5/animation/clip","value":["walk", "*"]}])",
     "objects[5].animation.clip[1]",
     {"stands alone"}},
    {"ClipListedTwice",
     R"([{"op":"replace","path":"/objects/5/animation/clip","value":["walk", "walk"]}])",
     "objects[5].animation.clip[1]",
     {"listed twice"}},
    {"ClipNotAName",
     R"([{"op":"replace","path":"/objects/5/animation/clip","value":3}])",
     "objects[5].animation.clip",
     {"expected a clip name, a list of names or \"*\", got a number"}},
    // Emitters.
    {"LifetimeZero",
     R"([{"op":"replace","path":"/emitters/0/lifetime","value":0}])",
     "emitters[0].lifetime",
     {"0 is out of range (0, 60]"}},
    {"LifetimeNegative",
     R"([{"op":"replace","path":"/emitters/0/lifetime","value":-1}])",
     "emitters[0].lifetime",
     {"out of range (0, 60]"}},
    {"TooManyParticles",
     R"([{"op":"replace","path":"/emitters/0/rate","value":10000},
         {"op":"replace","path":"/emitters/0/lifetime","value":60}])",
     "emitters[0].rate",
     {"particles alive at once; at most 100000"}},
    {"AlphaAboveOne",
     R"([{"op":"replace","path":"/emitters/0/startColor/3","value":2}])",
     "emitters[0].startColor[3]",
     {"alpha 2 is out of range [0, 1]"}},
    {"ColorOfThree",
     R"([{"op":"replace","path":"/emitters/0/endColor","value":[1,1,1]}])",
     "emitters[0].endColor",
     {"expected 4 numbers, got 3"}},
    {"UnknownEmitterKind",
     R"([{"op":"replace","path":"/emitters/0/kind","value":"lava"}])",
     "emitters[0].kind",
     {"allowed: fire, smoke, sparks"}},
    {"RateNegative",
     R"([{"op":"replace","path":"/emitters/0/rate","value":-5}])",
     "emitters[0].rate",
     {"out of range (0, 10000]"}},
    {"RateNotANumber",
     R"([{"op":"replace","path":"/emitters/0/rate","value":"NaN"}])",
     "emitters[0].rate",
     {"expected a number"}},
    {"SpinTooFast",
     R"([{"op":"replace","path":"/emitters/0/spin","value":1e9}])",
     "emitters[0].spin",
     {"out of range [-3600, 3600]"}},
    {"SpreadNegative",
     R"([{"op":"replace","path":"/emitters/0/spread","value":-1}])",
     "emitters[0].spread",
     {"out of range [0, 100]"}},
    // Clouds.
    {"CloudBottomAtTop",
     R"([{"op":"replace","path":"/clouds/0/bottom","value":55}])",
     "clouds[0].bottom",
     {"55 is not below top (55)"}},
    {"CloudBottomAboveTop",
     R"([{"op":"replace","path":"/clouds/0/bottom","value":60}])",
     "clouds[0].bottom",
     {"not below top"}},
    {"StepsNegative",
     R"([{"op":"replace","path":"/clouds/0/steps","value":-1}])",
     "clouds[0].steps",
     {"-1 is out of range [0, 512]"}},
    {"StepsTooMany",
     R"([{"op":"replace","path":"/clouds/0/steps","value":513}])",
     "clouds[0].steps",
     {"513 is out of range [0, 512]"}},
    {"ThresholdAboveOne",
     R"([{"op":"replace","path":"/clouds/0/threshold","value":1.5}])",
     "clouds[0].threshold",
     {"1.5 is out of range [0, 1]"}},
    {"NoiseLayersCount",
     R"([{"op":"remove","path":"/clouds/0/noise/1"}])",
     "clouds[0].noise",
     {"expected 2 noise layers, got 1"}},
    {"NoiseScaleZero",
     R"([{"op":"replace","path":"/clouds/0/noise/1/scale","value":0}])",
     "clouds[0].noise[1].scale",
     {"out of range (0, 100]"}},
    // Post effects.
    {"DepthOfFieldWithoutLens",
     R"([{"op":"remove","path":"/camera/lens"},{"op":"add","path":"/camera/fovY","value":50}])",
     "postEffects.depthOfField",
     {"needs a physical lens"}},
    {"UnknownPreset",
     R"([{"op":"replace","path":"/postEffects/colorMatrix/preset","value":"greyscale"}])",
     "postEffects.colorMatrix.preset",
     {"did you mean \"grayscale\"", "allowed: identity, grayscale, sepia, invert"}},
    {"UnknownToneOperator",
     R"([{"op":"replace","path":"/postEffects/toneMap/operator","value":"hable"}])",
     "postEffects.toneMap.operator",
     {"allowed: clip, reinhard, filmic"}},
    // The names before scene files and lessons shared one tone-curve vocabulary.
    {"RenamedToneOperatorAces",
     R"([{"op":"replace","path":"/postEffects/toneMap/operator","value":"aces"}])",
     "postEffects.toneMap.operator",
     {"\"aces\" is now called \"filmic\"", "allowed: clip, reinhard, filmic"}},
    {"RenamedToneOperatorLinear",
     R"([{"op":"replace","path":"/postEffects/toneMap/operator","value":"linear"}])",
     "postEffects.toneMap.operator",
     {"\"linear\" is now called \"clip\""}},
    {"BloomLevelsZero",
     R"([{"op":"replace","path":"/postEffects/bloom/levels","value":0}])",
     "postEffects.bloom.levels",
     {"out of range [1, 8]"}},
    {"BloomKneeAboveOne",
     R"([{"op":"replace","path":"/postEffects/bloom/knee","value":2}])",
     "postEffects.bloom.knee",
     {"out of range [0, 1]"}},
    {"ExposureZero",
     R"([{"op":"replace","path":"/postEffects/toneMap/exposure","value":0}])",
     "postEffects.toneMap.exposure",
     {"out of range (0, 1000]"}},
    {"EffectNotObject",
     R"([{"op":"replace","path":"/postEffects/bloom","value":true}])",
     "postEffects.bloom",
     {"expected an object, got a boolean"}},
};

INSTANTIATE_TEST_SUITE_P(Loader, SceneErrors, ::testing::ValuesIn(kBadFields),
                         [](const auto& test) { return std::string(test.param.name); });

// Numbers JSON cannot hold as finite doubles: nlohmann refuses them while parsing, and the loader still
// names the field.
TEST(SceneErrors, OverflowingNumberNamesItsField) {
    std::string text = scene_test::readFixture("every_field.json");
    std::string before = "\"emissive\": [8, 4, 1]";
    auto at = text.find(before);
    ASSERT_NE(at, std::string::npos);
    text.replace(at, before.size(), "\"emissive\": [8, 1e400, 1]");
    expectRefused(text, "objects[2].material.emissive[1]", {"1e400", "not finite"});
}

TEST(SceneErrors, NegativeOverflowNamesItsField) {
    std::string text =
        R"({"name": "x", "camera": {"position": [0, 1, 2], "target": [0, 0, 0], "near": -1e999}})";
    expectRefused(text, "camera.near", {"-1e999", "not finite"});
}

TEST(SceneErrors, TopLevelMustBeAnObject) {
    expectRefused("[1, 2]", "(top level)", {"expected an object, got an array"});
}

TEST(SceneErrors, MissingSceneFileIsNamed) {
    auto file = scene_test::dataDir() / "no_such_scene.json";
    auto scene = fx::loadScene(file, scene_test::testOptions());
    ASSERT_FALSE(scene.ok());
    EXPECT_TRUE(contains(scene.error(), file.string())) << scene.error();
}

TEST(SceneErrors, DeepNestingIsRefusedNotACrash) {
    std::string deep =
        R"({"name": "deep", "camera": {"position": [0, 1, 2], "target": [0, 0, 0]}, "objects": )";
    deep += std::string(100000, '[') + std::string(100000, ']') + "}";
    // Refused by the parser at the nesting limit (32 levels: the top object, "objects" and 30 more).
    std::string path = "objects";
    for (int level = 0; level < 31; ++level) path += "[0]";
    expectRefused(deep, path, {"nest more than 32 deep"});
}

// Scenes a hostile or broken file can be: each refused with a message naming the file and the reason.
TEST(SceneErrors, ARepeatedKeyIsAnErrorNotLastOneWins) {
    expectRefused(
        R"({"name": "a", "camera": {"position": [0, 1, 2], "near": 0.1, "near": 5, "target": [0, 0, 0]}})",
        "camera.near", {"appears twice in the same object"});
}

TEST(SceneErrors, NulBytesAreRefusedWithTheirPosition) {
    std::string valid = R"({"name": "a", "camera": {"position": [0, 1, 2], "target": [0, 0, 0]}})";
    for (const std::string& text : {valid + std::string(1, '\0'), std::string(64, '\0')}) {
        auto scene = fx::parseScene(text, nominalFile(), scene_test::testOptions());
        ASSERT_FALSE(scene.ok()) << "a NUL byte was accepted";
        EXPECT_TRUE(contains(scene.error(), "a NUL byte")) << scene.error();
        EXPECT_FALSE(contains(scene.error(), "unexpected end of input")) << scene.error();
    }
    auto trailing = fx::parseScene(valid + std::string(1, '\0'), nominalFile(), scene_test::testOptions());
    EXPECT_TRUE(contains(trailing.error(), "patched_every_field.json:1:70:")) << trailing.error();
    auto empty = fx::parseScene("  \n", nominalFile(), scene_test::testOptions());
    ASSERT_FALSE(empty.ok());
    EXPECT_TRUE(contains(empty.error(), "only white space")) << empty.error();
}

TEST(SceneErrors, AFolderGivenAsASceneSaysItIsAFolder) {
    auto scene = fx::loadScene(scene_test::dataDir(), scene_test::testOptions());
    ASSERT_FALSE(scene.ok());
    EXPECT_TRUE(contains(scene.error(), "is a folder, not a scene file")) << scene.error();
    EXPECT_FALSE(contains(scene.error(), "unexpected end of input")) << scene.error();
}

TEST(SceneErrors, AHugeStringIsRefusedAndQuotedOnlyInPart) {
    std::string huge(16 * 1024 * 1024, 'x');
    auto scene = fx::parseScene(
        R"({"name": ")" + huge + R"(", "camera": {"position": [0, 1, 2], "target": [0, 0, 0]}})",
        nominalFile(), scene_test::testOptions());
    ASSERT_FALSE(scene.ok());
    EXPECT_TRUE(contains(scene.error(), ": name: a string of 16777216 bytes"))
        << scene.error().substr(0, 300);
    EXPECT_TRUE(contains(scene.error(), "at most 4096")) << scene.error().substr(0, 300);
    EXPECT_LT(scene.error().size(), 400u);
    // An unknown enum value is quoted in part too.
    std::string longType(3000, 'q');
    auto light = fx::parseScene(R"({"name": "a", "camera": {"position": [0, 1, 2], "target": [0, 0, 0]},
        "lights": [{"type": ")" + longType +
                                    R"(", "direction": [0, -1, 0]}]})",
                                nominalFile(), scene_test::testOptions());
    ASSERT_FALSE(light.ok());
    EXPECT_TRUE(contains(light.error(), "(3000 bytes)")) << light.error().substr(0, 300);
    EXPECT_LT(light.error().size(), 400u);
}

TEST(SceneErrors, TooManyObjectsAreRefusedBeforeAnyIsRead) {
    std::string objects;
    for (int i = 0; i < 100000; ++i)
        objects += std::string(i ? "," : "") + R"({"primitive": {"shape": "box"}})";
    auto scene = fx::parseScene(
        R"({"name": "a", "camera": {"position": [0, 1, 2], "target": [0, 0, 0]}, "objects": [)" + objects +
            "]}",
        nominalFile(), scene_test::testOptions());
    ASSERT_FALSE(scene.ok());
    EXPECT_TRUE(contains(scene.error(), ": objects: 100000 entries; a scene may have at most 4096"))
        << scene.error();
    // As many point lights as the GPU list holds (lesson 10 lights 1024), written one by one.
    auto withLights = [&](int count, const std::string& grids) {
        std::string lights;
        for (int i = 0; i < count; ++i)
            lights += std::string(i ? "," : "") + R"({"type": "point", "position": [0, 1, 0]})";
        return fx::parseScene(
            R"({"name": "a", "camera": {"position": [0, 1, 2], "target": [0, 0, 0]}, "lights": [)" + lights +
                "]" + grids + "}",
            nominalFile(), scene_test::testOptions());
    };
    auto many = withLights(300, "");
    EXPECT_TRUE(many.ok()) << many.error();
    auto tooMany = withLights(1100, "");
    ASSERT_FALSE(tooMany.ok());
    EXPECT_TRUE(contains(tooMany.error(), ": lights: 1100 entries; a scene may have at most 1024"))
        << tooMany.error();
    // One list for both forms: 300 lights and a 32 x 32 grid are 1324 point lights.
    auto both = withLights(300, R"(, "lightGrids": [{"center": [0, 1, 0], "count": [32, 32]}])");
    ASSERT_FALSE(both.ok());
    EXPECT_TRUE(contains(both.error(),
                         "lightGrids[0].count: the scene's point lights and grids make 1324 lights "
                         "together; at most 1024"))
        << both.error();
}

}  // namespace
