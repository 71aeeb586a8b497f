// glTF loading: small documents written here (buffers as base64 data URIs) for each accessor form
// the loader must read, broken documents that must be refused with a reason, and the generated
// character in res/models.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include <sys/stat.h>
#include <unistd.h>

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "scene/gltf_loader.hpp"
#include "scene_test_support.hpp"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::string base64(const std::vector<unsigned char>& bytes) {
    static const char* kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        unsigned v = unsigned(bytes[i]) << 16;
        if (i + 1 < bytes.size()) v |= unsigned(bytes[i + 1]) << 8;
        if (i + 2 < bytes.size()) v |= bytes[i + 2];
        out += kAlphabet[(v >> 18) & 63];
        out += kAlphabet[(v >> 12) & 63];
        out += i + 1 < bytes.size() ? kAlphabet[(v >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? kAlphabet[v & 63] : '=';
    }
    return out;
}

// Builds a one-buffer glTF document: append data, get accessors, then finish() to text.
class Doc {
public:
    Doc() {
        doc_["asset"] = {{"version", "2.0"}};
        doc_["accessors"] = json::array();
        doc_["bufferViews"] = json::array();
    }
    template <class T>
    int accessor(const std::vector<T>& values, int componentType, const char* type, std::size_t count,
                 bool normalized = false) {
        while (bytes_.size() % 4) bytes_.push_back(0);
        std::size_t offset = bytes_.size();
        bytes_.resize(offset + values.size() * sizeof(T));
        std::memcpy(bytes_.data() + offset, values.data(), values.size() * sizeof(T));
        doc_["bufferViews"].push_back(
            {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", values.size() * sizeof(T)}});
        json a = {{"bufferView", doc_["bufferViews"].size() - 1},
                  {"componentType", componentType},
                  {"count", count},
                  {"type", type}};
        if (normalized) a["normalized"] = true;
        doc_["accessors"].push_back(a);
        return int(doc_["accessors"].size()) - 1;
    }
    int floats(const std::vector<float>& v, const char* type, int components) {
        return accessor(v, 5126, type, v.size() / std::size_t(components));
    }
    json& operator[](const char* key) { return doc_[key]; }
    std::string finish() {
        json d = doc_;
        if (bytes_.empty()) return d.dump();  // tinygltf refuses an empty data URI
        d["buffers"] = json::array({{{"byteLength", bytes_.size()},
                                     {"uri", "data:application/octet-stream;base64," + base64(bytes_)}}});
        return d.dump();
    }

private:
    json doc_;
    std::vector<unsigned char> bytes_;
};

// A unit quad in XY (4 vertices, 2 triangles) with the index width given.
std::string quad(int indexType, bool withNormals = true, bool withUvs = true) {
    Doc d;
    int pos = d.floats({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, "VEC3", 3);
    json attributes = {{"POSITION", pos}};
    if (withNormals) attributes["NORMAL"] = d.floats({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3", 3);
    if (withUvs) attributes["TEXCOORD_0"] = d.floats({0, 1, 1, 1, 1, 0, 0, 0.25f}, "VEC2", 2);
    int indices;
    std::vector<unsigned> idx = {0, 1, 2, 0, 2, 3};
    if (indexType == 5121) {
        indices = d.accessor(std::vector<std::uint8_t>(idx.begin(), idx.end()), 5121, "SCALAR", 6);
    } else if (indexType == 5123) {
        indices = d.accessor(std::vector<std::uint16_t>(idx.begin(), idx.end()), 5123, "SCALAR", 6);
    } else {
        indices = d.accessor(std::vector<std::uint32_t>(idx.begin(), idx.end()), 5125, "SCALAR", 6);
    }
    d["meshes"] = json::array(
        {{{"name", "quad"}, {"primitives", {{{"attributes", attributes}, {"indices", indices}}}}}});
    d["nodes"] = json::array({{{"mesh", 0}}});
    return d.finish();
}

fx::Result<fx::GltfModel> parse(const std::string& text) {
    return fx::parseGltf(text, FXLAB_TEST_DATA, "test.gltf");
}

TEST(GltfLoader, ReadsEightSixteenAndThirtyTwoBitIndicesAlike) {
    std::vector<std::uint32_t> expected = {0, 1, 2, 0, 2, 3};
    for (int type : {5121, 5123, 5125}) {
        SCOPED_TRACE(type);
        auto model = parse(quad(type));
        ASSERT_TRUE(model.ok()) << model.error();
        ASSERT_EQ(model->meshes.size(), 1u);
        const auto& mesh = model->meshes[0].primitives.at(0).mesh;
        EXPECT_EQ(mesh.indices, expected);
        EXPECT_EQ(mesh.vertexCount(), 4u);
        EXPECT_EQ(mesh.positions[2], glm::vec3(1, 1, 0));
        EXPECT_EQ(mesh.normals[3], glm::vec3(0, 0, 1));
        EXPECT_EQ(model->roots, std::vector<int>{0});
        EXPECT_TRUE(model->warnings.empty());
    }
}

TEST(GltfLoader, FlipsTextureCoordinatesToGlConvention) {
    auto model = parse(quad(5123));
    ASSERT_TRUE(model.ok()) << model.error();
    const auto& uvs = model->meshes[0].primitives[0].mesh.uvs;
    // File (0, 1) is the image's bottom-left: GL's (0, 0). File v = 0.25 becomes 0.75.
    EXPECT_EQ(uvs[0], glm::vec2(0, 0));
    EXPECT_EQ(uvs[2], glm::vec2(1, 1));
    EXPECT_EQ(uvs[3], glm::vec2(0, 0.75f));
}

TEST(GltfLoader, MissingNormalsAreComputedAndMissingUvsAreZero) {
    auto model = parse(quad(5125, false, false));
    ASSERT_TRUE(model.ok()) << model.error();
    const auto& prim = model->meshes[0].primitives[0];
    EXPECT_TRUE(prim.generatedNormals);
    for (const auto& n : prim.mesh.normals) {
        EXPECT_NEAR(n.z, 1.0f, 1e-6f);  // counter-clockwise in XY: facing +Z
    }
    for (const auto& uv : prim.mesh.uvs) EXPECT_EQ(uv, glm::vec2(0));
}

TEST(GltfLoader, ComputedNormalsOfUnusedVerticesAreNotNaN) {
    fx::MeshData mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {5, 5, 5}};
    mesh.indices = {0, 1, 2};  // a degenerate (zero-area) triangle; vertex 3 in none
    fx::computeNormals(mesh);
    for (const auto& n : mesh.normals) EXPECT_EQ(n, glm::vec3(0, 1, 0));
}

// Two joints on a chain, a skinned quad, and a clip with step, linear and cubic-spline channels.
std::string skinnedDocument() {
    Doc d;
    int pos = d.floats({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, "VEC3", 3);
    int joints = d.accessor(std::vector<std::uint16_t>{0, 1, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0}, 5123,
                            "VEC4", 4);
    int weights = d.floats({1, 0, 0, 0, 0.5f, 0.5f, 0, 0, 1, 0, 0, 0, 0.25f, 0.75f, 0, 0}, "VEC4", 4);
    int indices = d.accessor(std::vector<std::uint16_t>{0, 1, 2, 0, 2, 3}, 5123, "SCALAR", 6);
    // Joint 0 at the origin, joint 1 one metre up: inverse binds are the opposite translations.
    glm::mat4 ib0(1.0f), ib1 = glm::translate(glm::mat4(1.0f), glm::vec3(0, -1, 0));
    std::vector<float> ibm;
    for (const glm::mat4* m : {&ib0, &ib1})
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) ibm.push_back((*m)[c][r]);
    int inverseBind = d.floats(ibm, "MAT4", 16);
    int times = d.floats({0, 1, 2}, "SCALAR", 1);
    int stepValues = d.floats({0, 0, 0, 2, 0, 0, 4, 0, 0}, "VEC3", 3);
    int cubicTimes = d.floats({0, 2}, "SCALAR", 1);
    int cubicValues = d.floats({0, 0, 0, 1, 1, 1, 0, 0, 0, 0, 0, 0, 2, 2, 2, 0, 0, 0}, "VEC3", 3);
    // Rotations as normalised shorts: (0, 0, 0, 1) and a quarter turn about Z.
    int rotations =
        d.accessor(std::vector<std::int16_t>{0, 0, 0, 32767, 0, 0, 23170, 23170}, 5122, "VEC4", 2, true);
    int rotationTimes = d.floats({0, 1}, "SCALAR", 1);
    d["meshes"] =
        json::array({{{"primitives",
                       {{{"attributes", {{"POSITION", pos}, {"JOINTS_0", joints}, {"WEIGHTS_0", weights}}},
                         {"indices", indices},
                         {"material", 0}}}}}});
    d["materials"] =
        json::array({{{"name", "glow"},
                      {"pbrMetallicRoughness",
                       {{"baseColorFactor", {0.5, 0.25, 1, 1}}, {"baseColorTexture", {{"index", 0}}}}},
                      {"emissiveFactor", {1, 0.5, 0}},
                      {"emissiveTexture", {{"index", 0}}},
                      {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 4}}}}}}});
    d["textures"] = json::array({{{"source", 0}}});
    d["images"] = json::array({{{"uri", "scenes/assets/crate.png"}}});
    d["nodes"] = json::array({
        {{"name", "body"}, {"mesh", 0}, {"skin", 0}},
        {{"name", "root"}, {"children", {2}}},
        {{"name", "bone"}, {"translation", {0, 1, 0}}},
        {{"name", "fixed"}, {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 7, 8, 9, 1}}},
    });
    d["scene"] = 0;
    d["scenes"] = json::array({{{"nodes", {0, 1, 3}}}});
    d["skins"] = json::array({{{"joints", {1, 2}}, {"inverseBindMatrices", inverseBind}}});
    d["animations"] = json::array({{
        {"name", "test"},
        {"samplers",
         {{{"input", times}, {"output", stepValues}, {"interpolation", "STEP"}},
          {{"input", cubicTimes}, {"output", cubicValues}, {"interpolation", "CUBICSPLINE"}},
          {{"input", rotationTimes}, {"output", rotations}}}},
        {"channels",
         {{{"sampler", 0}, {"target", {{"node", 2}, {"path", "translation"}}}},
          {{"sampler", 1}, {"target", {{"node", 2}, {"path", "scale"}}}},
          {{"sampler", 2}, {"target", {{"node", 1}, {"path", "rotation"}}}}}},
    }});
    return d.finish();
}

TEST(GltfLoader, ReadsSkinsHierarchyMaterialsAndClips) {
    auto model = parse(skinnedDocument());
    ASSERT_TRUE(model.ok()) << model.error();
    EXPECT_TRUE(model->warnings.empty()) << model->warnings.front();
    // Hierarchy.
    ASSERT_EQ(model->nodes.size(), 4u);
    EXPECT_EQ(model->nodes[2].parent, 1);
    EXPECT_EQ(model->nodes[1].children, std::vector<int>{2});
    EXPECT_EQ(model->roots, (std::vector<int>{0, 1, 3}));
    EXPECT_EQ(model->nodes[2].rest.translation, glm::vec3(0, 1, 0));
    EXPECT_TRUE(model->nodes[3].hasMatrix);
    EXPECT_EQ(model->nodes[3].matrix[3], glm::vec4(7, 8, 9, 1));
    // Skin.
    ASSERT_EQ(model->skins.size(), 1u);
    EXPECT_EQ(model->skins[0].joints, (std::vector<int>{1, 2}));
    EXPECT_EQ(model->skins[0].inverseBindMatrices[1][3], glm::vec4(0, -1, 0, 1));
    const auto& prim = model->meshes[0].primitives[0];
    ASSERT_TRUE(prim.skinned());
    EXPECT_EQ(prim.influences[1].joints[1], 1);
    EXPECT_EQ(prim.influences[3].weights, glm::vec4(0.25f, 0.75f, 0, 0));
    // Material: factors, the emissive strength extension, texture files resolved against the base folder.
    ASSERT_EQ(model->materials.size(), 1u);
    const auto& m = model->materials[0];
    EXPECT_EQ(m.baseColor, glm::vec4(0.5f, 0.25f, 1, 1));
    EXPECT_EQ(m.emissive, glm::vec3(4, 2, 0));
    EXPECT_EQ(m.baseColorTexture, 0);
    EXPECT_EQ(m.emissiveTexture, 0);
    EXPECT_EQ(model->textures[0].file, fs::path(FXLAB_TEST_DATA) / "scenes/assets/crate.png");
    // Clip: step, cubic spline, normalised-short rotations.
    const fx::AnimationClip* clip = model->findClip("test");
    ASSERT_NE(clip, nullptr);
    EXPECT_FLOAT_EQ(clip->duration, 2.0f);
    ASSERT_EQ(clip->channels.size(), 3u);
    EXPECT_EQ(clip->channels[0].interpolation, fx::Interpolation::step);
    EXPECT_EQ(fx::sampleChannel(clip->channels[0], 1.5f), glm::vec4(2, 0, 0, 0));
    EXPECT_EQ(fx::sampleChannel(clip->channels[0], 2.0f), glm::vec4(4, 0, 0, 0));
    EXPECT_EQ(clip->channels[1].interpolation, fx::Interpolation::cubicSpline);
    EXPECT_NEAR(fx::sampleChannel(clip->channels[1], 1.0f).x, 1.5f,
                1e-6f);  // halfway between 1 and 2, flat tangents
    EXPECT_EQ(clip->channels[2].interpolation, fx::Interpolation::linear);
    glm::quat q = fx::toQuat(fx::sampleChannel(clip->channels[2], 1.0f));
    EXPECT_NEAR(q.z, std::sqrt(0.5f), 1e-4f);
    EXPECT_NEAR(q.w, std::sqrt(0.5f), 1e-4f);
}

TEST(GltfLoader, SkinnedVerticesFollowTheAnimatedJoints) {
    auto model = parse(skinnedDocument());
    ASSERT_TRUE(model.ok()) << model.error();
    auto pose = fx::restPose(model->nodes);
    fx::applyClip(*model->findClip("test"), 1.0f, pose);
    auto world = fx::worldMatrices(model->nodes, pose);
    auto joints = fx::jointMatrices(model->skins[0], world, world[0]);
    // At t = 1: root turned 90 degrees about Z; bone translated to (2, 0, 0) in root space and scaled 1.5.
    // Vertex 0 (weight 1 on the root) at the origin stays there.
    const auto& prim = model->meshes[0].primitives[0];
    auto v0 = fx::skinVertex(prim.mesh.positions[0], {0, 0, 1}, prim.influences[0], joints);
    EXPECT_NEAR(glm::length(v0.position), 0.0f, 1e-4f);
    // Vertex 2 at (1, 1, 0), weight 1 on the bone: bind-local (1, 0, 0) -> scaled (1.5, 0, 0) ->
    // moved (3.5, 0, 0) -> turned to (0, 3.5, 0).
    auto v2 = fx::skinVertex(prim.mesh.positions[2], {0, 0, 1}, prim.influences[2], joints);
    EXPECT_NEAR(v2.position.x, 0.0f, 1e-3f);
    EXPECT_NEAR(v2.position.y, 3.5f, 1e-3f);
}

TEST(GltfLoader, RefusesIndicesBeyondTheVertices) {
    Doc d;
    int pos = d.floats({0, 0, 0, 1, 0, 0, 1, 1, 0}, "VEC3", 3);
    int indices = d.accessor(std::vector<std::uint16_t>{0, 1, 3}, 5123, "SCALAR", 3);
    d["meshes"] = json::array(
        {{{"name", "bad"}, {"primitives", {{{"attributes", {{"POSITION", pos}}}, {"indices", indices}}}}}});
    auto model = parse(d.finish());
    ASSERT_FALSE(model.ok());
    EXPECT_TRUE(scene_test::contains(model.error(), "test.gltf")) << model.error();
    EXPECT_TRUE(
        scene_test::contains(model.error(), "mesh 'bad' primitive 0: index 3 is beyond the 3 vertices"))
        << model.error();
}

TEST(GltfLoader, RefusesAccessorsThatReadPastTheirBuffer) {
    Doc d;
    int pos = d.floats({0, 0, 0, 1, 0, 0, 1, 1, 0}, "VEC3", 3);
    d["accessors"][std::size_t(pos)]["count"] = 30;
    d["meshes"] = json::array({{{"primitives", {{{"attributes", {{"POSITION", pos}}}}}}}});
    auto model = parse(d.finish());
    ASSERT_FALSE(model.ok());
    EXPECT_TRUE(scene_test::contains(model.error(), "past the end")) << model.error();
}

TEST(GltfLoader, RefusesKeyTimesThatGoBackwards) {
    Doc d;
    int times = d.floats({0, 2, 1}, "SCALAR", 1);
    int values = d.floats({0, 0, 0, 1, 1, 1, 2, 2, 2}, "VEC3", 3);
    d["nodes"] = json::array({json::object()});
    d["animations"] =
        json::array({{{"name", "bad"},
                      {"samplers", {{{"input", times}, {"output", values}}}},
                      {"channels", {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "translation"}}}}}}}});
    auto model = parse(d.finish());
    ASSERT_FALSE(model.ok());
    EXPECT_TRUE(scene_test::contains(model.error(), "animation 'bad' channel 0: key times decrease at key 2"))
        << model.error();
}

TEST(GltfLoader, RefusesNodesWithTwoParents) {
    Doc d;
    d["nodes"] = json::array({{{"children", {2}}}, {{"children", {2}}}, {{"name", "shared"}}});
    auto model = parse(d.finish());
    ASSERT_FALSE(model.ok());
    EXPECT_TRUE(scene_test::contains(model.error(), "node 'shared' has more than one parent"))
        << model.error();
}

TEST(GltfLoader, BadFilesComeBackAsErrors) {
    auto missing = fx::loadGltf(fs::path(FXLAB_TEST_DATA) / "no_such_model.gltf");
    ASSERT_FALSE(missing.ok());
    EXPECT_TRUE(scene_test::contains(missing.error(), "no_such_model.gltf: no such file")) << missing.error();
    auto syntax = parse("{\"asset\": {\"version\": \"2.0\"}, \"nodes\": [");
    ASSERT_FALSE(syntax.ok());
    EXPECT_TRUE(scene_test::contains(syntax.error(), "test.gltf")) << syntax.error();
}

TEST(GltfLoader, MissingTextureFilesAreWarningsAndDrawnWithout) {
    Doc d;
    d["materials"] = json::array({{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}});
    d["textures"] = json::array({{{"source", 0}}});
    d["images"] = json::array({{{"uri", "nowhere/missing.png"}}});
    auto model = parse(d.finish());
    ASSERT_TRUE(model.ok()) << model.error();
    EXPECT_FALSE(model->warnings.empty());
    EXPECT_TRUE(model->textures[0].file.string().find("missing.png") != std::string::npos);
}

// The character that tools/assetgen writes (res/models/character.gltf).
class GeneratedCharacter : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        auto loaded = fx::loadGltf(scene_test::resDir() / "models/character.gltf");
        if (loaded.ok()) {
            model_ = new fx::GltfModel(std::move(*loaded));
        } else {
            error_ = loaded.error();
        }
    }
    static void TearDownTestSuite() {
        delete model_;
        model_ = nullptr;
    }
    void SetUp() override { ASSERT_NE(model_, nullptr) << error_; }
    static fx::GltfModel* model_;
    static std::string error_;
};
fx::GltfModel* GeneratedCharacter::model_ = nullptr;
std::string GeneratedCharacter::error_;

TEST_F(GeneratedCharacter, HasTenOrMoreJointsAndAWalkClip) {
    EXPECT_TRUE(model_->warnings.empty()) << model_->warnings.front();
    ASSERT_EQ(model_->skins.size(), 1u);
    EXPECT_GE(model_->skins[0].jointCount(), 10u);
    const fx::AnimationClip* walk = model_->findClip("walk");
    ASSERT_NE(walk, nullptr);
    EXPECT_GT(walk->duration, 0.5f);
    EXPECT_LT(walk->duration, 2.0f);
    EXPECT_GE(walk->channels.size(), 10u);
}

TEST_F(GeneratedCharacter, EveryVertexWeightSumsToOne) {
    std::size_t skinnedVertices = 0;
    for (const auto& mesh : model_->meshes) {
        for (const auto& prim : mesh.primitives) {
            ASSERT_TRUE(prim.skinned());
            for (const auto& inf : prim.influences) {
                float sum = inf.weights.x + inf.weights.y + inf.weights.z + inf.weights.w;
                ASSERT_NEAR(sum, 1.0f, 1e-3f);
                for (int c = 0; c < 4; ++c) {
                    if (inf.weights[c] > 0) {
                        ASSERT_LT(inf.joints[c], model_->skins[0].jointCount());
                    }
                }
                ++skinnedVertices;
            }
        }
    }
    EXPECT_GT(skinnedVertices, 500u);
}

TEST_F(GeneratedCharacter, RestPoseJointMatricesAreIdentity) {
    int meshNode = model_->meshNodes().at(0);
    auto world = fx::worldMatrices(model_->nodes, fx::restPose(model_->nodes));
    auto joints = fx::jointMatrices(model_->skins[0], world, world[std::size_t(meshNode)]);
    for (const auto& m : joints)
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) EXPECT_NEAR(m[c][r], c == r ? 1.0f : 0.0f, 1e-5f);
}

TEST_F(GeneratedCharacter, WalkMovesTheLegsAndLoopsSeamlessly) {
    const fx::AnimationClip& walk = *model_->findClip("walk");
    int meshNode = model_->meshNodes().at(0);
    auto jointsAt = [&](float t) {
        auto pose = fx::restPose(model_->nodes);
        fx::applyClip(walk, t, pose);
        auto world = fx::worldMatrices(model_->nodes, pose);
        return fx::jointMatrices(model_->skins[0], world, world[std::size_t(meshNode)]);
    };
    auto start = jointsAt(0.0f), end = jointsAt(walk.duration), quarter = jointsAt(walk.duration / 4);
    float loopError = 0, motion = 0;
    for (std::size_t j = 0; j < start.size(); ++j)
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) {
                loopError = std::max(loopError, std::abs(start[j][c][r] - end[j][c][r]));
                motion = std::max(motion, std::abs(start[j][c][r] - quarter[j][c][r]));
            }
    EXPECT_LT(loopError, 1e-5f) << "the last key should repeat the first";
    EXPECT_GT(motion, 0.2f) << "a quarter cycle in, the limbs should have moved";
    // Played far past its length: the wrapped time gives the same pose as the equivalent short time.
    double hours = 1000.0 * 3600.0 + 0.25 * walk.duration;
    auto late = jointsAt(fx::clipTime(hours, walk.duration));
    for (std::size_t j = 0; j < late.size(); ++j)
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) {
                ASSERT_TRUE(std::isfinite(late[j][c][r]));
                EXPECT_NEAR(late[j][c][r], quarter[j][c][r], 1e-4f);
            }
}

TEST_F(GeneratedCharacter, MaterialsAndTexturesResolve) {
    ASSERT_GE(model_->materials.size(), 2u);
    bool textured = false, glowing = false;
    for (const auto& m : model_->materials) {
        if (m.baseColorTexture >= 0) {
            textured = true;
            EXPECT_TRUE(fs::exists(model_->textures[std::size_t(m.baseColorTexture)].file));
        }
        if (std::max({m.emissive.r, m.emissive.g, m.emissive.b}) > 1.0f) glowing = true;
    }
    EXPECT_TRUE(textured);
    EXPECT_TRUE(glowing) << "the visor's emissive strength should lift it above 1";
}

}  // namespace

namespace {

// A mesh of one triangle plus a one-channel animation, for the hostile-number tests below.
struct Hostile {
    Doc d;
    int positions, indices, times, values;
    Hostile() {
        positions = d.floats({0, 0, 0, 1, 0, 0, 1, 1, 0}, "VEC3", 3);
        indices = d.accessor(std::vector<std::uint16_t>{0, 1, 2}, 5123, "SCALAR", 3);
        values = d.floats({0, 0, 0, 1, 1, 1}, "VEC3", 3);
        times = d.floats({0, 1}, "SCALAR", 1);  // last: its data ends the buffer
        d["meshes"] = json::array(
            {{{"primitives", {{{"attributes", {{"POSITION", positions}}}, {"indices", indices}}}}}});
        d["nodes"] = json::array({{{"mesh", 0}}});
        d["animations"] = json::array(
            {{{"name", "move"},
              {"samplers", {{{"input", times}, {"output", values}}}},
              {"channels", {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "translation"}}}}}}}});
    }
    json& accessor(int index) { return d["accessors"][std::size_t(index)]; }
};

}  // namespace

// 2^62 elements of 4 bytes at the end of the buffer: stride * (count - 1) + 4 wraps around to a small
// number, which passed the old bounds check and let the animation reader walk off the heap buffer.
TEST(GltfLoader, HugeCountsAreRefusedNotWrappedAround) {
    for (std::uint64_t count : {std::uint64_t(1) << 62, std::uint64_t(1) << 63, ~std::uint64_t(0)}) {
        for (const char* which : {"times", "positions", "indices"}) {
            SCOPED_TRACE(std::string(which) + " " + std::to_string(count));
            Hostile h;
            int index = std::string(which) == "times"       ? h.times
                        : std::string(which) == "positions" ? h.positions
                                                            : h.indices;
            h.accessor(index)["count"] = count;
            auto model = parse(h.d.finish());
            ASSERT_FALSE(model.ok());
            EXPECT_TRUE(scene_test::contains(model.error(), "test.gltf")) << model.error();
            EXPECT_TRUE(scene_test::contains(model.error(), "elements")) << model.error();
        }
    }
}

TEST(GltfLoader, AnAccessorWithoutDataCannotAskForUnboundedMemory) {
    Hostile h;
    h.accessor(h.positions).erase("bufferView");  // all zeros, as many as it says
    h.accessor(h.positions)["count"] = std::uint64_t(1) << 40;
    auto model = parse(h.d.finish());
    ASSERT_FALSE(model.ok());
    EXPECT_TRUE(scene_test::contains(model.error(), "fxlab reads at most 16777216 per accessor"))
        << model.error();
}

TEST(GltfLoader, HugeOffsetsAndStridesAreRefused) {
    struct Case {
        const char* what;
        std::function<void(Hostile&)> mutate;
        const char* expected;
    };
    std::vector<Case> cases = {
        {"view offset", [](Hostile& h) { h.d["bufferViews"][0]["byteOffset"] = ~std::uint64_t(0) - 4; },
         "lies outside its buffer"},
        {"view length", [](Hostile& h) { h.d["bufferViews"][0]["byteLength"] = ~std::uint64_t(0); },
         "lies outside its buffer"},
        {"accessor offset", [](Hostile& h) { h.accessor(h.positions)["byteOffset"] = ~std::uint64_t(0) - 8; },
         "reads past the end of buffer view"},
        {"stride", [](Hostile& h) { h.d["bufferViews"][0]["byteStride"] = 252; },
         "reads past the end of buffer view"},
        {"stride below an element", [](Hostile& h) { h.d["bufferViews"][0]["byteStride"] = 4; },
         "less than one element"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.what);
        Hostile h;
        c.mutate(h);
        auto model = parse(h.d.finish());
        ASSERT_FALSE(model.ok());
        EXPECT_TRUE(scene_test::contains(model.error(), "test.gltf")) << model.error();
    }
}

TEST(GltfLoader, AFloatJointsAccessorIsNamedAsTheWrongTypeNotAsReadingPastTheBuffer) {
    Doc d;
    int pos = d.floats({0, 0, 0, 1, 0, 0, 1, 1, 0}, "VEC3", 3);
    // Joints written as bytes (12 bytes) but declared float: read as float it would need 48 bytes.
    int joints = d.accessor(std::vector<std::uint8_t>{0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}, 5126, "VEC4", 3);
    int weights = d.floats({1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0}, "VEC4", 4);
    d["meshes"] = json::array(
        {{{"primitives",
           {{{"attributes", {{"POSITION", pos}, {"JOINTS_0", joints}, {"WEIGHTS_0", weights}}}}}}}});
    auto model = parse(d.finish());
    ASSERT_FALSE(model.ok());
    EXPECT_TRUE(
        scene_test::contains(model.error(), "JOINTS_0: must be unsigned 8- or 16-bit VEC4, not float"))
        << model.error();
}

TEST(GltfLoader, RequiredExtensionsFxlabDoesNotImplementAreRefusedByName) {
    std::string text = quad(5123);
    json doc = json::parse(text);
    doc["extensionsUsed"] = {"KHR_draco_mesh_compression"};
    doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    auto model = parse(doc.dump());
    ASSERT_FALSE(model.ok());
    EXPECT_TRUE(scene_test::contains(
        model.error(), "requires the extension KHR_draco_mesh_compression, which fxlab does not implement"))
        << model.error();
    // Used but not required: loaded, with a warning naming it.
    doc.erase("extensionsRequired");
    doc["extensionsUsed"] = {"EXT_texture_webp"};
    auto used = parse(doc.dump());
    ASSERT_TRUE(used.ok()) << used.error();
    ASSERT_EQ(used->warnings.size(), 1u);
    EXPECT_TRUE(scene_test::contains(used->warnings[0], "EXT_texture_webp")) << used->warnings[0];
}

TEST(GltfLoader, AFolderOrDeviceIsRefusedWithTheReadersReason) {
    auto folder = fx::loadGltf(FXLAB_TEST_DATA);
    ASSERT_FALSE(folder.ok());
    EXPECT_TRUE(scene_test::contains(folder.error(), "is a folder")) << folder.error();
    auto device = fx::loadGltf("/dev/zero");
    ASSERT_FALSE(device.ok());
    EXPECT_TRUE(scene_test::contains(device.error(), "character device")) << device.error();
}

// Refusals tinygltf gives without a reason, or with one that hides the rule: fxlab finds the rule first.
TEST(GltfLoader, ASkinWithoutJointsIsRefusedNamingTheRule) {
    // Khronos' RiggedFigure sample was refused with "tinygltf refused it without giving a reason".
    json doc = json::parse(quad(5123));
    doc["skins"] = json::array({{{"name", "rig"}, {"skeleton", 0}}});
    doc["nodes"][0]["skin"] = 0;
    auto model = parse(doc.dump());
    ASSERT_FALSE(model.ok());
    EXPECT_TRUE(scene_test::contains(model.error(), "skin 0 'rig': has no \"joints\"")) << model.error();
    EXPECT_TRUE(scene_test::contains(model.error(), "skin.joints")) << model.error();
    EXPECT_FALSE(scene_test::contains(model.error(), "without giving a reason")) << model.error();
}

TEST(GltfLoader, DracoGeometryWithoutAnUncompressedCopyIsRefusedNamingDraco) {
    // Draco used but not listed as required, the accessors without data: tinygltf said only
    // "accessor[N] invalid bufferView".
    json doc = json::parse(quad(5123));
    json& primitive = doc["meshes"][0]["primitives"][0];
    doc["accessors"][primitive["indices"].get<int>()].erase("bufferView");
    primitive["extensions"] = {
        {"KHR_draco_mesh_compression", {{"bufferView", 0}, {"attributes", {{"POSITION", 0}}}}}};
    doc["extensionsUsed"] = {"KHR_draco_mesh_compression"};
    auto model = parse(doc.dump());
    ASSERT_FALSE(model.ok());
    EXPECT_TRUE(scene_test::contains(model.error(),
                                     "mesh 0 'quad' primitive 0: compressed with Draco "
                                     "(KHR_draco_mesh_compression)"))
        << model.error();
    EXPECT_FALSE(scene_test::contains(model.error(), "invalid bufferView")) << model.error();
}

TEST(GltfLoader, DracoWithAnUncompressedCopyLoadsTheCopy) {
    json doc = json::parse(quad(5123));
    doc["meshes"][0]["primitives"][0]["extensions"] = {
        {"KHR_draco_mesh_compression", {{"bufferView", 0}, {"attributes", {{"POSITION", 0}}}}}};
    doc["extensionsUsed"] = {"KHR_draco_mesh_compression"};
    auto model = parse(doc.dump());
    ASSERT_TRUE(model.ok()) << model.error();
    EXPECT_EQ(model->meshes.at(0).primitives.at(0).mesh.vertexCount(), 4u);
}

TEST(GltfLoader, TheSameRulesHoldForABinaryFile) {
    // A .glb holding the skin without joints: the JSON chunk is checked before tinygltf sees it.
    json doc = json::parse(quad(5123));
    doc["skins"] = json::array({{{"name", "rig"}}});
    std::string chunk = doc.dump();
    while (chunk.size() % 4) chunk += ' ';
    std::string glb = "glTF";
    auto word = [&](std::uint32_t v) {
        for (int i = 0; i < 4; ++i) glb += char((v >> (8 * i)) & 0xFF);
    };
    word(2);
    word(std::uint32_t(12 + 8 + chunk.size()));
    word(std::uint32_t(chunk.size()));
    glb += "JSON";
    glb += chunk;
    auto model =
        fx::parseGltfBytes(std::as_bytes(std::span(glb.data(), glb.size())), FXLAB_TEST_DATA, "test.glb");
    ASSERT_FALSE(model.ok());
    EXPECT_TRUE(scene_test::contains(model.error(), "test.glb: skin 0 'rig': has no \"joints\""))
        << model.error();
}

// The models' vertices over all objects are bounded (each object draws its own copy on the GPU): a scene
// exactly at the limit loads, one vertex more is refused naming the object and the total.
TEST(GltfLoader, TheScenesVerticesOverAllObjectsAreBounded) {
    auto model = [](int vertices) {
        Doc d;
        int pos = d.floats(std::vector<float>(std::size_t(vertices) * 3, 0.0f), "VEC3", 3);
        int idx = d.accessor(std::vector<std::uint32_t>{0, 1, 2}, 5125, "SCALAR", 3);
        d["meshes"] =
            json::array({{{"primitives", {{{"attributes", {{"POSITION", pos}}}, {"indices", idx}}}}}});
        d["nodes"] = json::array({{{"mesh", 0}}});
        return d.finish();
    };
    const fs::path dir = fs::temp_directory_path() / ("fx_vertex_budget_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    ASSERT_TRUE(fx::writeFileAtomically(dir / "a.gltf", model(2048)).ok());
    ASSERT_TRUE(fx::writeFileAtomically(dir / "b.gltf", model(2049)).ok());
    auto scene = [&](const char* last) {
        json objects = json::array();
        for (int i = 0; i < 4096; ++i)
            objects.push_back({{"name", "o" + std::to_string(i)}, {"gltf", i == 4095 ? last : "a.gltf"}});
        fx::SceneLoadOptions options;
        options.assetRoot = dir;
        return fx::parseScene(json{{"name", "many objects"},
                                   {"camera", {{"position", {0, 2, 8}}, {"target", {0, 0, 0}}}},
                                   {"objects", objects}}
                                  .dump(),
                              dir / "s.json", options);
    };
    auto at = scene("a.gltf");  // 4096 x 2048 = 2^23
    EXPECT_TRUE(at.ok()) << at.error();
    auto over = scene("b.gltf");
    ASSERT_FALSE(over.ok());
    EXPECT_TRUE(scene_test::contains(over.error(),
                                     "objects[4095].gltf: the models of objects[0] to objects[4095] "
                                     "have 8388609 vertices together"))
        << over.error();
    fs::remove_all(dir);
}

// Issue 40, defects 4, 5 and 10: a buffer or image URI that is a FIFO hung the lesson forever
// (tinygltf's own FileExists opens the file); "../", "%2e%2e" and links read files from anywhere;
// tinygltf's own words ("File not found : ...") were the message.
namespace {

struct ModelFolder {
    fs::path root = fs::temp_directory_path() / ("fx_gltf_uris_" + std::to_string(::getpid()));
    ModelFolder() {
        fs::remove_all(root);
        fs::create_directories(root / "model");
        std::FILE* f = std::fopen((root / "outside.bin").c_str(), "wb");
        std::fwrite("abcd", 1, 4, f);
        std::fclose(f);
        f = std::fopen((root / "model" / "inside.bin").c_str(), "wb");
        std::fwrite("abcd", 1, 4, f);
        std::fclose(f);
        ::mkfifo((root / "model" / "pipe.bin").c_str(), 0600);
        ::mkfifo((root / "pipe-outside").c_str(), 0600);
        fs::create_symlink(root / "outside.bin", root / "model" / "link.bin");
        fs::create_symlink(root / "model" / "pipe.bin", root / "model" / "link-to-pipe.bin");
        fs::create_symlink("/dev/zero", root / "model" / "zero.bin");
    }
    ~ModelFolder() { fs::remove_all(root); }
    fs::path write(const std::string& kind, const std::string& uri) const {
        nlohmann::json doc = {{"asset", {{"version", "2.0"}}}};
        if (kind == "buffers")
            doc["buffers"] = {{{"uri", uri}, {"byteLength", 4}}};
        else
            doc["images"] = {{{"uri", uri}}};
        const fs::path file = root / "model" / "m.gltf";
        std::FILE* f = std::fopen(file.c_str(), "wb");
        const std::string text = doc.dump();
        std::fwrite(text.data(), 1, text.size(), f);
        std::fclose(f);
        return file;
    }
};

// loadGltf, or a failure (and the end of the test program) when it does not return within 20 s.
fx::Result<fx::GltfModel> loadWithin(const fs::path& file) {
    auto result = std::make_shared<std::optional<fx::Result<fx::GltfModel>>>();
    auto done = std::make_shared<std::atomic<bool>>(false);
    std::thread([file, result, done] {
        *result = fx::loadGltf(file);
        *done = true;
    }).detach();
    for (int i = 0; i < 200 && !*done; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(100));
    if (!*done) {
        ADD_FAILURE() << file << ": loadGltf did not return within 20 s (a blocking read)";
        std::_Exit(1);
    }
    return std::move(**result);
}

}  // namespace

TEST(GltfLoader, EveryUriStaysInTheModelsFolderAndIsReadOnlyWhenARegularFile) {
    ModelFolder m;
    struct Case {
        const char* kind;
        const char* uri;
        const char* says;
    };
    const Case refused[] = {
        {"buffers", "pipe.bin", "buffers[0].uri \"pipe.bin\": "},
        {"buffers", "link-to-pipe.bin", "is a FIFO (named pipe)"},
        {"images", "pipe.bin", "images[0].uri \"pipe.bin\": "},
        {"buffers", "zero.bin", "which is outside the model's folder"},
        {"buffers", "../outside.bin", "buffers[0].uri: \"../outside.bin\" resolves to"},
        {"buffers", "%2e%2e/outside.bin", "which is outside the model's folder"},
        {"buffers", "link.bin", "which is outside the model's folder"},
        {"images", "../pipe-outside", "images[0].uri: \"../pipe-outside\" resolves to"},
        {"images", "/etc/passwd", "a glTF file may only name files in its own folder or below it"},
    };
    for (const Case& c : refused) {
        auto model = loadWithin(m.write(c.kind, c.uri));
        ASSERT_FALSE(model.ok()) << c.uri;
        EXPECT_TRUE(scene_test::contains(model.error(), "m.gltf: ")) << model.error();
        EXPECT_TRUE(scene_test::contains(model.error(), c.says)) << model.error();
        EXPECT_FALSE(scene_test::contains(model.error(), "File read error")) << model.error();
        EXPECT_FALSE(scene_test::contains(model.error(), "File not found")) << model.error();
    }
    auto fine = loadWithin(m.write("buffers", "inside.bin"));
    ASSERT_TRUE(fine.ok()) << fine.error();
    // A missing buffer in fxlab's words, not tinygltf's.
    auto missing = loadWithin(m.write("buffers", "gone.bin"));
    ASSERT_FALSE(missing.ok());
    EXPECT_TRUE(scene_test::contains(missing.error(), "buffers[0].uri \"gone.bin\": ")) << missing.error();
    EXPECT_TRUE(scene_test::contains(missing.error(), "gone.bin: no such file")) << missing.error();
    EXPECT_FALSE(scene_test::contains(missing.error(), "File not found")) << missing.error();
}
