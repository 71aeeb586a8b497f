// Static props and the ground: plain meshes with textures, one with a small node hierarchy.
#include <cmath>

#include <glm/gtc/quaternion.hpp>

#include "assetgen.hpp"
#include "geometry/mesh_data.hpp"
#include "gltf_builder.hpp"

namespace fx::assetgen {
namespace {

Json material(const char* name, glm::vec3 color, int texture = -1) {
    Json factor = decimals(color);
    factor.push_back(1.0);
    Json pbr = {{"baseColorFactor", factor}, {"metallicFactor", 0.0}, {"roughnessFactor", 0.9}};
    if (texture >= 0) pbr["baseColorTexture"] = {{"index", texture}};
    return {{"name", name}, {"pbrMetallicRoughness", pbr}};
}

// A primitive from a MeshData (texture coordinates flipped to glTF's top-left origin).
Json primitive(GltfBuilder& gltf, const MeshData& mesh, int materialIndex, bool wideIndices,
               float uvScale = 1.0f) {
    std::vector<glm::vec3> positions, normals;
    for (const auto& p : mesh.positions) positions.push_back(snap(p));
    for (const auto& n : mesh.normals) normals.push_back(snap(n));
    std::vector<glm::vec2> uvs;
    for (const auto& uv : mesh.uvs) uvs.emplace_back(uv.x * uvScale, 1.0f - uv.y * uvScale);
    Json attributes = {{"POSITION", gltf.addPositions(positions)},
                       {"NORMAL", gltf.addVec3(normals)},
                       {"TEXCOORD_0", gltf.addVec2(uvs)}};
    int indices = wideIndices ? gltf.addIndices32(mesh.indices) : gltf.addIndices16(mesh.indices);
    return {{"attributes", attributes}, {"indices", indices}, {"material", materialIndex}};
}

Json yRotation(float degrees) {
    glm::quat q = glm::angleAxis(glm::radians(degrees), glm::vec3(0, 1, 0));
    return Json::array({0.0, decimal(snap(q.y)), 0.0, decimal(snap(q.w))});
}

}  // namespace

GeneratedModel makeCrate() {
    GltfBuilder gltf("crate.bin");
    int planks = gltf.addTexture(gltf.addImage("../textures/crate_planks.png"));
    gltf.addMaterial(material("planks", {1.0f, 1.0f, 1.0f}, planks));
    gltf.addMesh({{"name", "crate"}, {"primitives", {primitive(gltf, makeBox(glm::vec3(1.0f)), 0, false)}}});
    // The box is centred on its node; the node lifts it so the model stands on y = 0.
    gltf.addNode({{"name", "crate"}, {"mesh", 0}, {"translation", {0.0, 0.5, 0.0}}});
    gltf.setSceneRoots({0});
    return {gltf.gltfText(), gltf.binBytes()};
}

GeneratedModel makeLantern() {
    GltfBuilder gltf("lantern.bin");
    gltf.addMaterial(material("iron", {0.18f, 0.17f, 0.16f}));
    Json glass = material("glass", {0.9f, 0.8f, 0.6f});
    glass["emissiveFactor"] = {1.0, 0.6, 0.25};
    glass["extensions"] = {{"KHR_materials_emissive_strength", {{"emissiveStrength", 6.0}}}};
    gltf.addMaterial(glass);
    gltf.useExtension("KHR_materials_emissive_strength");
    gltf.addMesh(
        {{"name", "post"}, {"primitives", {primitive(gltf, makeCylinder(0.05f, 2.0f, 12), 0, false)}}});
    gltf.addMesh({{"name", "lamp"},
                  {"primitives", {primitive(gltf, makeBox(glm::vec3(0.2f, 0.26f, 0.2f)), 1, false)}}});
    gltf.addMesh({{"name", "cap"},
                  {"primitives", {primitive(gltf, makeBox(glm::vec3(0.3f, 0.05f, 0.3f)), 0, false)}}});
    // lantern -> post, lamp -> cap: the lamp turns 45 degrees and the cap on it turns with it.
    gltf.addNode({{"name", "lantern"}, {"children", {1, 2}}});
    gltf.addNode({{"name", "post"}, {"mesh", 0}, {"translation", {0.0, 1.0, 0.0}}});
    gltf.addNode({{"name", "lamp"},
                  {"mesh", 1},
                  {"translation", {0.0, 2.13, 0.0}},
                  {"rotation", yRotation(45.0f)},
                  {"children", {3}}});
    gltf.addNode({{"name", "cap"}, {"mesh", 2}, {"translation", {0.0, 0.155, 0.0}}});
    gltf.setSceneRoots({0});
    return {gltf.gltfText(), gltf.binBytes()};
}

GeneratedModel makeGround() {
    GltfBuilder gltf("ground.bin");
    int checker = gltf.addTexture(gltf.addImage("../textures/ground_checker.png"));
    gltf.addMaterial(material("ground", {1.0f, 1.0f, 1.0f}, checker));
    // 32-bit indices on purpose: the loader reads both widths, and this model exercises the wide one.
    gltf.addMesh(
        {{"name", "ground"}, {"primitives", {primitive(gltf, makePlane(20.0f, 20.0f), 0, true, 10.0f)}}});
    gltf.addNode({{"name", "ground"}, {"mesh", 0}});
    gltf.setSceneRoots({0});
    return {gltf.gltfText(), gltf.binBytes()};
}

}  // namespace fx::assetgen
