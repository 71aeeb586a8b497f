// GPU skinning against the CPU reference: the generated character's joint matrices (read back from the
// SSBO) and skinned vertices (read back from the transform-feedback buffer) at a given time, the hard
// cases of bad weights, and the two ways of drawing a skinned mesh giving the same picture.
#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "base/paths.hpp"
#include "effects/scene/gpu_model.hpp"
#include "effects/scene/gpu_skinning.hpp"
#include "effects/scene/scene_meshes.hpp"
#include "gl/framebuffer.hpp"
#include "gl/program.hpp"
#include "gl/readback.hpp"
#include "gl_test.hpp"
#include "scene/gltf_loader.hpp"
#include "scene/scene_loader.hpp"

using namespace fx;

namespace {

std::vector<PosedVertex> readPosed(const SkinnedMesh& mesh) {
    std::vector<PosedVertex> out(static_cast<std::size_t>(mesh.vertexCount()));
    glGetNamedBufferSubData(mesh.posedBuffer(), 0, static_cast<GLsizeiptr>(out.size() * sizeof(PosedVertex)),
                            out.data());
    return out;
}

float maxDifference(const glm::mat4& a, const glm::mat4& b) {
    float d = 0;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) d = std::max(d, std::abs(a[c][r] - b[c][r]));
    return d;
}

std::shared_ptr<const GltfModel> character() {
    auto model = loadGltf(resourceDir() / "models/character.gltf");
    EXPECT_TRUE(model.ok()) << (model.ok() ? "" : model.error());
    return model.ok() ? std::make_shared<const GltfModel>(std::move(*model)) : nullptr;
}

}  // namespace

class Skinning : public GlTest {
protected:
    GpuSkinning skinning;
    void SetUp() override {
        GlTest::SetUp();
        ASSERT_TRUE(programsBuilt());
    }
};

TEST_F(Skinning, CharacterJointMatricesAndVerticesMatchTheCpuAtAGivenTime) {
    auto model = character();
    ASSERT_TRUE(model);
    MaterialTextures textures;
    GpuModel gpu(model, textures, "character");
    const AnimationClip* walk = model->findClip("walk");
    ASSERT_NE(walk, nullptr);
    const float t = 0.37f;
    gpu.animate(walk, t, &skinning);
    EXPECT_EQ(skinning.posedMeshes(), gpu.skinnedMeshes());

    // The CPU reference, computed here from the model alone.
    auto pose = restPose(model->nodes);
    applyClip(*walk, t, pose);
    auto world = worldMatrices(model->nodes, pose);
    int meshNode = model->meshNodes().at(0);
    const Skin& skin = model->skins.at(std::size_t(model->nodes[std::size_t(meshNode)].skin));
    auto reference = jointMatrices(skin, world, world[std::size_t(meshNode)]);
    ASSERT_GE(reference.size(), 10u);

    // Joint matrices: what the SSBO holds equals the CPU's.
    const auto& uploaded = gpu.jointMatrices(meshNode);
    ASSERT_EQ(uploaded.size(), reference.size());
    float jointError = 0, motion = 0;
    for (std::size_t j = 0; j < reference.size(); ++j) {
        jointError = std::max(jointError, maxDifference(uploaded[j], reference[j]));
        motion = std::max(motion, maxDifference(reference[j], glm::mat4(1.0f)));
    }
    EXPECT_LT(jointError, 1e-6f);
    EXPECT_GT(motion, 0.1f) << "at t = 0.37 the walk should have moved the joints from the bind pose";

    // Skinned vertices: the transform-feedback output equals skinVertex() on the CPU.
    const auto& mesh = model->meshes[std::size_t(model->nodes[std::size_t(meshNode)].mesh)];
    float positionError = 0, normalError = 0, moved = 0;
    std::size_t checked = 0;
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
        const SkinnedMesh* skinned = gpu.skinnedMesh(meshNode, p);
        ASSERT_NE(skinned, nullptr);
        auto posed = readPosed(*skinned);
        const ModelPrimitive& prim = mesh.primitives[p];
        ASSERT_EQ(posed.size(), prim.mesh.vertexCount());
        for (std::size_t i = 0; i < posed.size(); ++i) {
            SkinnedVertex cpu =
                skinVertex(prim.mesh.positions[i], prim.mesh.normals[i], prim.influences[i], reference);
            glm::vec3 gpuPosition(posed[i].position[0], posed[i].position[1], posed[i].position[2]);
            glm::vec3 gpuNormal(posed[i].normal[0], posed[i].normal[1], posed[i].normal[2]);
            positionError = std::max(positionError, glm::length(gpuPosition - cpu.position));
            normalError = std::max(normalError, glm::length(gpuNormal - cpu.normal));
            moved = std::max(moved, glm::length(cpu.position - prim.mesh.positions[i]));
            EXPECT_EQ(posed[i].texcoord[0], prim.mesh.uvs[i].x);
            ++checked;
        }
    }
    EXPECT_GT(checked, 500u);
    EXPECT_LT(positionError, 2e-5f) << "metres";
    EXPECT_LT(normalError, 1e-4f);
    EXPECT_GT(moved, 0.05f);
}

TEST_F(Skinning, SsboHoldsTheUploadedMatrices) {
    JointMatrixBuffer buffer("test joints");
    std::vector<glm::mat4> m = {glm::translate(glm::mat4(1.0f), glm::vec3(1, 2, 3)), glm::mat4(2.0f)};
    buffer.upload(m);
    std::vector<glm::mat4> back(2);
    glGetNamedBufferSubData(buffer.name(), 0, 2 * sizeof(glm::mat4), back.data());
    EXPECT_EQ(back[0], m[0]);
    EXPECT_EQ(back[1], m[1]);
    // Growing replaces the buffer and keeps the new contents.
    std::vector<glm::mat4> more(40, glm::mat4(3.0f));
    buffer.upload(more);
    EXPECT_EQ(buffer.jointCount(), 40u);
    glm::mat4 last;
    glGetNamedBufferSubData(buffer.name(), 39 * sizeof(glm::mat4), sizeof(glm::mat4), glm::value_ptr(last));
    EXPECT_EQ(last, glm::mat4(3.0f));
}

TEST_F(Skinning, BadWeightsFollowTheCpuRuleAndStayFinite) {
    // One vertex per bad weight of the Shader effects chapter's hard case 19.
    MeshData mesh;
    std::vector<JointInfluence> influences;
    auto add = [&](glm::vec3 p, JointInfluence inf) {
        mesh.positions.push_back(p);
        mesh.normals.push_back({0, 1, 0});
        mesh.uvs.push_back({0, 0});
        influences.push_back(inf);
    };
    JointInfluence zero;  // all weights 0: the zero matrix would put the vertex at w = 0
    JointInfluence heavy;
    heavy.joints[0] = 0, heavy.joints[1] = 1, heavy.weights = {1.0f, 1.0f, 0, 0};  // sum 2: would double w
    JointInfluence outOfRange;
    outOfRange.joints[0] = 1, outOfRange.joints[1] = 500, outOfRange.weights = {0.5f, 0.5f, 0, 0};
    JointInfluence negative;
    negative.joints[0] = 0, negative.joints[1] = 1, negative.weights = {1.5f, -0.5f, 0, 0};
    JointInfluence onlyInvalid;
    onlyInvalid.joints[0] = 7, onlyInvalid.weights = {1, 0, 0, 0};
    add({1, 2, 3}, zero);
    add({1, 0, 0}, heavy);
    add({0, 1, 0}, outOfRange);
    add({0, 0, 1}, negative);
    add({2, 2, 2}, onlyInvalid);
    mesh.indices = {0, 1, 2, 2, 3, 4};
    SkinnedMesh skinned(mesh, influences, "bad weights");
    EXPECT_EQ(skinned.unweightedVertices(),
              1u);  // only the all-zero one is known unweighted before the palette

    std::vector<glm::mat4> palette = {glm::translate(glm::mat4(1.0f), glm::vec3(10, 0, 0)),
                                      glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(0, 0, 1))};
    JointMatrixBuffer joints("bad weights joints");
    joints.upload(palette);
    skinning.pose(skinned, joints);
    auto posed = readPosed(skinned);
    for (std::size_t i = 0; i < posed.size(); ++i) {
        SCOPED_TRACE(i);
        SkinnedVertex cpu = skinVertex(mesh.positions[i], mesh.normals[i], influences[i], palette);
        for (int c = 0; c < 3; ++c) {
            ASSERT_TRUE(std::isfinite(posed[i].position[c]));
            EXPECT_NEAR(posed[i].position[c], cpu.position[std::size_t(c)], 1e-5f);
            EXPECT_NEAR(posed[i].normal[c], cpu.normal[std::size_t(c)], 1e-5f);
        }
    }
    // The all-zero vertex and the one with only invalid joints keep their bind positions.
    EXPECT_EQ(glm::vec3(posed[0].position[0], posed[0].position[1], posed[0].position[2]),
              glm::vec3(1, 2, 3));
    EXPECT_EQ(glm::vec3(posed[4].position[0], posed[4].position[1], posed[4].position[2]),
              glm::vec3(2, 2, 2));
    // Weights summing to 2 are renormalised: halfway between the two joints' results, not twice as far.
    EXPECT_NEAR(posed[1].position[0], 5.5f, 1e-5f);
    EXPECT_NEAR(posed[1].position[1], 0.5f, 1e-5f);
}

TEST_F(Skinning, PosedAndInShaderSkinningDrawTheSamePicture) {
    auto model = character();
    ASSERT_TRUE(model);
    MaterialTextures textures;
    GpuModel gpu(model, textures, "character");
    gpu.animate(model->findClip("walk"), 0.6f, &skinning);

    auto litFragment = "lessons/01_program_objects/normals.frag";
    auto posedProgram =
        gl::Program::build({"lessons/01_program_objects/lit.vert", litFragment, {}, {}, "posed"});
    ASSERT_TRUE(posedProgram.ok()) << posedProgram.error();
    auto sourceProgram =
        gl::Program::build({"effects/scene/skinned_scene.vert", litFragment, {}, {}, "skinned"});
    ASSERT_TRUE(sourceProgram.ok()) << sourceProgram.error();

    const int size = 96;
    auto render = [&](const gl::Program& program, SkinnedDraw mode) {
        gl::Texture color = gl::Texture::create2D(TextureFormat::RGBA8, size, size, 1, "skinning.color");
        gl::Texture depth = gl::Texture::create2D(TextureFormat::Depth32F, size, size, 1, "skinning.depth");
        gl::Framebuffer fbo("skinning.fbo");
        fbo.attachColor(0, color);
        fbo.attachDepth(depth);
        fbo.setDrawBuffers(1);
        EXPECT_TRUE(fbo.checkComplete().ok());
        glBindFramebuffer(GL_FRAMEBUFFER, fbo.name());
        glViewport(0, 0, size, size);
        // The GL tests share one context: set every state this draw depends on.
        glDepthMask(GL_TRUE);
        glDepthFunc(GL_LESS);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glDisable(GL_BLEND);
        glDisable(GL_CULL_FACE);
        glEnable(GL_DEPTH_TEST);
        glClearColor(0, 0, 0, 1);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glm::mat4 vp = glm::perspective(glm::radians(40.0f), 1.0f, 0.1f, 20.0f) *
                       glm::lookAt(glm::vec3(2.0f, 1.2f, 3.0f), glm::vec3(0, 0.9f, 0), glm::vec3(0, 1, 0));
        glProgramUniformMatrix4fv(program.name(), glsl::kViewProjectionLocation, 1, GL_FALSE,
                                  glm::value_ptr(vp));
        ModelDrawStyle style;
        style.setMaterial = false;  // the normals program has no material uniforms
        style.skinned = mode;
        gpu.draw(program.name(), glm::mat4(1.0f), style);
        glDisable(GL_DEPTH_TEST);
        glBindFramebuffer(GL_FRAMEBUFFER, context().presentFramebuffer());
        return gl::readTexture(color);
    };
    FloatImage posed = render(*posedProgram, SkinnedDraw::posed);
    FloatImage source = render(*sourceProgram, SkinnedDraw::source);
    ASSERT_EQ(posed.texels.size(), source.texels.size());
    std::size_t covered = 0, different = 0;
    for (std::size_t i = 0; i < posed.texels.size(); i += 4) {
        bool a = posed.texels[i] + posed.texels[i + 1] + posed.texels[i + 2] > 0;
        covered += a;
        float d = 0;
        for (int c = 0; c < 3; ++c)
            d = std::max(d, std::abs(posed.texels[i + std::size_t(c)] - source.texels[i + std::size_t(c)]));
        different += d > 2.0f / 255.0f;
    }
    EXPECT_GT(covered, std::size_t(size * size / 20)) << "the character should cover part of the picture";
    // Same vertices through two paths: at most a few edge pixels differ by rounding.
    EXPECT_LE(different, covered / 100 + 2);
}

TEST_F(Skinning, SceneMeshesPoseTheCharacterAtTheFrameTime) {
    SceneLoadOptions options;
    options.assetRoot = resourceDir();
    auto scene = loadScene(resourceDir() / "scenes/02_skinned_shadows.json", options);
    ASSERT_TRUE(scene.ok()) << scene.error();
    SceneMeshes meshes(*scene);
    EXPECT_TRUE(meshes.notDrawn().empty()) << meshes.notDrawn().front();
    EXPECT_EQ(meshes.skinnedObjects(), 2u);  // the character and the lattice mannequin
    std::size_t character = 0;
    while (character < scene->objects.size() && scene->objects[character].name != "character") ++character;
    const GpuModel* model = meshes.model(character);
    ASSERT_NE(model, nullptr);
    int node = model->model().meshNodes().at(0);
    const SkinnedMesh* skinned = model->skinnedMesh(node, 0);
    ASSERT_NE(skinned, nullptr);

    meshes.update(0.25);
    auto early = readPosed(*skinned);
    EXPECT_FLOAT_EQ(meshes.clipTime(character), 0.25f);
    // Hours later, the same phase of the loop: the same pose, exactly (the time is wrapped in double).
    meshes.update(0.25 + 3600.0 * 10);
    auto late = readPosed(*skinned);
    EXPECT_FLOAT_EQ(meshes.clipTime(character), 0.25f);
    float difference = 0;
    for (std::size_t i = 0; i < early.size(); ++i)
        for (int c = 0; c < 3; ++c)
            difference = std::max(difference, std::abs(early[i].position[c] - late[i].position[c]));
    EXPECT_LT(difference, 1e-6f);
    // A different time, a different pose.
    meshes.update(0.75);
    auto other = readPosed(*skinned);
    float change = 0;
    for (std::size_t i = 0; i < early.size(); ++i)
        for (int c = 0; c < 3; ++c)
            change = std::max(change, std::abs(early[i].position[c] - other[i].position[c]));
    EXPECT_GT(change, 0.05f);
    EXPECT_EQ(meshes.skinningUpdates(), 3u);
    // draw() at a time update() has not posed poses first.
    glBindFramebuffer(GL_FRAMEBUFFER, context().presentFramebuffer());
    auto program = gl::Program::build(
        {"lessons/01_program_objects/lit.vert", "lessons/01_program_objects/lit.frag", {}, {}, "lit"});
    ASSERT_TRUE(program.ok()) << program.error();
    meshes.draw(program->name(), *scene, 1.5);
    EXPECT_EQ(meshes.skinningUpdates(), 4u);
    meshes.draw(program->name(), *scene, 1.5);
    EXPECT_EQ(meshes.skinningUpdates(), 4u) << "the same time is not posed twice";
    glBindVertexArray(0);
}
