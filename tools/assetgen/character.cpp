// The skinned character: a figure of capsules and boxes on a 17-joint skeleton, with a walk cycle
// ("walk", 1 s, linear keys) and an idle clip ("idle", 2 s: breathing by scale, linear; the head
// turning by step keys).
#include <algorithm>
#include <array>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "assetgen.hpp"
#include "geometry/mesh_data.hpp"
#include "gltf_builder.hpp"

namespace fx::assetgen {
namespace {

struct JointSpec {
    const char* name;
    int parent;
    glm::vec3 offset;  // from the parent joint, in the bind pose (no rotations at rest)
};

// The character faces +Z; its left is +X. Heights in metres (about 1.88 m to the top of the head).
constexpr int kHips = 0, kSpine = 1, kChest = 2, kNeck = 3, kHead = 4;
constexpr int kUpperArmL = 5, kForearmL = 6, kHandL = 7, kUpperArmR = 8, kForearmR = 9, kHandR = 10;
constexpr int kThighL = 11, kShinL = 12, kFootL = 13, kThighR = 14, kShinR = 15, kFootR = 16;
const JointSpec kJoints[] = {
    {"hips", -1, {0.0f, 0.95f, 0.0f}},
    {"spine", kHips, {0.0f, 0.1f, 0.0f}},
    {"chest", kSpine, {0.0f, 0.2f, 0.0f}},
    {"neck", kChest, {0.0f, 0.26f, 0.0f}},
    {"head", kNeck, {0.0f, 0.1f, 0.0f}},
    {"upper_arm.L", kChest, {0.2f, 0.22f, 0.0f}},
    {"forearm.L", kUpperArmL, {0.0f, -0.28f, 0.0f}},
    {"hand.L", kForearmL, {0.0f, -0.25f, 0.0f}},
    {"upper_arm.R", kChest, {-0.2f, 0.22f, 0.0f}},
    {"forearm.R", kUpperArmR, {0.0f, -0.28f, 0.0f}},
    {"hand.R", kForearmR, {0.0f, -0.25f, 0.0f}},
    {"thigh.L", kHips, {0.1f, -0.06f, 0.0f}},
    {"shin.L", kThighL, {0.0f, -0.42f, 0.0f}},
    {"foot.L", kShinL, {0.0f, -0.4f, 0.0f}},
    {"thigh.R", kHips, {-0.1f, -0.06f, 0.0f}},
    {"shin.R", kThighR, {0.0f, -0.42f, 0.0f}},
    {"foot.R", kShinR, {0.0f, -0.4f, 0.0f}},
};
constexpr int kJointCount = static_cast<int>(std::size(kJoints));

enum MaterialId { kSuit, kSkin, kVisor, kBoots, kMaterialCount };

enum class Shape { box, capsule };

// One rigid piece of the body, bound to a joint; near the joint it blends into the parent joint over
// `blend` metres along `axis` (the direction from the joint into the piece).
struct Part {
    int joint;
    Shape shape;
    glm::vec3 size;  // box: extents; capsule: (radius, height, -)
    glm::vec3 centre;
    glm::vec3 axis;
    float blend;
    MaterialId material;
};

const glm::vec3 kUp(0, 1, 0), kDown(0, -1, 0);
const Part kParts[] = {
    {kHips, Shape::box, {0.3f, 0.16f, 0.19f}, {0.0f, 0.93f, 0.0f}, kUp, 0.0f, kSuit},
    {kSpine, Shape::capsule, {0.11f, 0.3f, 0}, {0.0f, 1.12f, 0.0f}, kUp, 0.06f, kSuit},
    {kChest, Shape::box, {0.36f, 0.3f, 0.2f}, {0.0f, 1.36f, 0.0f}, kUp, 0.05f, kSuit},
    {kNeck, Shape::capsule, {0.05f, 0.16f, 0}, {0.0f, 1.56f, 0.0f}, kUp, 0.03f, kSkin},
    {kHead, Shape::capsule, {0.11f, 0.27f, 0}, {0.0f, 1.74f, 0.0f}, kUp, 0.03f, kSkin},
    {kHead, Shape::box, {0.17f, 0.05f, 0.04f}, {0.0f, 1.77f, 0.1f}, kUp, 0.0f, kVisor},
    {kUpperArmL, Shape::capsule, {0.055f, 0.34f, 0}, {0.2f, 1.33f, 0.0f}, kDown, 0.05f, kSuit},
    {kForearmL, Shape::capsule, {0.048f, 0.3f, 0}, {0.2f, 1.07f, 0.0f}, kDown, 0.05f, kSuit},
    {kHandL, Shape::box, {0.06f, 0.1f, 0.08f}, {0.2f, 0.88f, 0.0f}, kDown, 0.02f, kSkin},
    {kUpperArmR, Shape::capsule, {0.055f, 0.34f, 0}, {-0.2f, 1.33f, 0.0f}, kDown, 0.05f, kSuit},
    {kForearmR, Shape::capsule, {0.048f, 0.3f, 0}, {-0.2f, 1.07f, 0.0f}, kDown, 0.05f, kSuit},
    {kHandR, Shape::box, {0.06f, 0.1f, 0.08f}, {-0.2f, 0.88f, 0.0f}, kDown, 0.02f, kSkin},
    {kThighL, Shape::capsule, {0.075f, 0.48f, 0}, {0.1f, 0.69f, 0.0f}, kDown, 0.06f, kSuit},
    {kShinL, Shape::capsule, {0.06f, 0.46f, 0}, {0.1f, 0.27f, 0.0f}, kDown, 0.05f, kSuit},
    {kFootL, Shape::box, {0.1f, 0.07f, 0.24f}, {0.1f, 0.035f, 0.05f}, kDown, 0.03f, kBoots},
    {kThighR, Shape::capsule, {0.075f, 0.48f, 0}, {-0.1f, 0.69f, 0.0f}, kDown, 0.06f, kSuit},
    {kShinR, Shape::capsule, {0.06f, 0.46f, 0}, {-0.1f, 0.27f, 0.0f}, kDown, 0.05f, kSuit},
    {kFootR, Shape::box, {0.1f, 0.07f, 0.24f}, {-0.1f, 0.035f, 0.05f}, kDown, 0.03f, kBoots},
};

// Capsule tessellation: enough to read as round at lesson sizes, small enough for a ~60 KB buffer.
constexpr int kCapsuleSegments = 12, kCapsuleCapRings = 3;

std::array<glm::vec3, kJointCount> bindPositions() {
    std::array<glm::vec3, kJointCount> world{};
    for (int j = 0; j < kJointCount; ++j) {
        const JointSpec& s = kJoints[j];
        world[std::size_t(j)] = (s.parent >= 0 ? world[std::size_t(s.parent)] : glm::vec3(0.0f)) + s.offset;
    }
    return world;
}

float smoothstep(float e0, float e1, float x) {
    float t = std::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

struct Primitive {
    MeshData mesh;
    std::vector<std::array<std::uint8_t, 4>> joints;
    std::vector<std::array<std::uint8_t, 4>> weights;  // normalised bytes: w = byte / 255
};

void addPart(Primitive& out, const Part& part, const std::array<glm::vec3, kJointCount>& jointWorld) {
    MeshData piece = part.shape == Shape::box
                         ? makeBox(part.size)
                         : makeCapsule(part.size.x, part.size.y, kCapsuleSegments, kCapsuleCapRings);
    auto base = static_cast<std::uint32_t>(out.mesh.positions.size());
    int parent = kJoints[part.joint].parent;
    glm::vec3 jointPos = jointWorld[std::size_t(part.joint)];
    for (std::size_t i = 0; i < piece.positions.size(); ++i) {
        glm::vec3 p = snap(piece.positions[i] + part.centre);
        out.mesh.positions.push_back(p);
        out.mesh.normals.push_back(snap(piece.normals[i]));
        out.mesh.uvs.push_back(piece.uvs[i]);
        // Weight of the part's own joint: 1 inside the part, 1/2 at the joint, falling to 0 `blend`
        // beyond it. Stored as bytes that add up to exactly 255, so the pair sums to 1.
        int own = 255;
        if (part.blend > 0.0f && parent >= 0) {
            float s = glm::dot(p - jointPos, part.axis);
            own = static_cast<int>(std::nearbyint(smoothstep(-part.blend, part.blend, s) * 255.0f));
        }
        if (own >= 255) {
            out.joints.push_back({std::uint8_t(part.joint), 0, 0, 0});
            out.weights.push_back({255, 0, 0, 0});
        } else if (own <= 0) {
            out.joints.push_back({std::uint8_t(parent), 0, 0, 0});
            out.weights.push_back({255, 0, 0, 0});
        } else {
            out.joints.push_back({std::uint8_t(part.joint), std::uint8_t(parent), 0, 0});
            out.weights.push_back({std::uint8_t(own), std::uint8_t(255 - own), 0, 0});
        }
    }
    for (std::uint32_t index : piece.indices) out.mesh.indices.push_back(base + index);
}

glm::quat euler(float xDeg, float yDeg, float zDeg) {
    // Z * Y * X, like the scene format's Euler angles.
    return glm::angleAxis(glm::radians(zDeg), glm::vec3(0, 0, 1)) *
           glm::angleAxis(glm::radians(yDeg), glm::vec3(0, 1, 0)) *
           glm::angleAxis(glm::radians(xDeg), glm::vec3(1, 0, 0));
}

glm::vec4 xyzw(const glm::quat& q) {
    return {q.x, q.y, q.z, q.w};
}

// Builds one animation channel set from a function of the cycle phase.
struct ClipBuilder {
    GltfBuilder& gltf;
    Json samplers = Json::array();
    Json channels = Json::array();

    void add(int node, const char* path, const char* interpolation, const std::vector<float>& times,
             const std::vector<glm::vec4>& values, bool vec3) {
        int input = gltf.addTimes(times);
        int output;
        if (vec3) {
            std::vector<glm::vec3> v3;
            for (const auto& v : values) v3.emplace_back(v);
            output = gltf.addVec3(v3);
        } else {
            output = gltf.addVec4(values);
        }
        samplers.push_back({{"input", input}, {"interpolation", interpolation}, {"output", output}});
        channels.push_back({{"sampler", static_cast<int>(samplers.size()) - 1},
                            {"target", {{"node", node}, {"path", path}}}});
    }
    Json finish(const char* name) const {
        return {{"name", name}, {"channels", channels}, {"samplers", samplers}};
    }
};

constexpr int kFirstJointNode = 2;  // node 0 holds the mesh, node 1 is the armature root

Json walkClip(GltfBuilder& gltf, const std::array<glm::vec3, kJointCount>& bind) {
    constexpr int kKeys = 17;  // 16 segments; the last key repeats the first, so the loop is seamless
    constexpr float kCycle = 1.0f;
    constexpr float kTwoPi = 6.2831853f;
    std::vector<float> times;
    for (int k = 0; k < kKeys; ++k) times.push_back(kCycle * float(k) / float(kKeys - 1));
    ClipBuilder clip{gltf};

    auto rotations = [&](int joint, auto angles) {
        std::vector<glm::vec4> values;
        for (int k = 0; k < kKeys; ++k) {
            float phase = kTwoPi * float(k % (kKeys - 1)) / float(kKeys - 1);
            glm::vec3 a = angles(phase);
            values.push_back(xyzw(euler(a.x, a.y, a.z)));
        }
        clip.add(kFirstJointNode + joint, "rotation", "LINEAR", times, values, false);
    };
    // Hips: bob down at each footfall (twice a cycle), sway toward the standing leg.
    std::vector<glm::vec4> hips;
    for (int k = 0; k < kKeys; ++k) {
        float phase = kTwoPi * float(k % (kKeys - 1)) / float(kKeys - 1);
        glm::vec3 p =
            bind[kHips] + glm::vec3(0.025f * std::sin(phase), -0.03f * std::cos(2.0f * phase) - 0.02f, 0.0f);
        hips.emplace_back(p, 0.0f);
    }
    clip.add(kFirstJointNode + kHips, "translation", "LINEAR", times, hips, true);
    rotations(kHips, [](float ph) { return glm::vec3(0.0f, 6.0f * std::sin(ph), 2.0f * std::sin(ph)); });
    rotations(kSpine, [](float ph) { return glm::vec3(4.0f, -3.0f * std::sin(ph), 0.0f); });
    rotations(kChest, [](float ph) { return glm::vec3(2.0f, -5.0f * std::sin(ph), -1.5f * std::sin(ph)); });
    rotations(kHead, [](float ph) {
        return glm::vec3(-4.0f + 2.0f * std::cos(2.0f * ph), 4.0f * std::sin(ph), 0.0f);
    });
    // Legs: the thigh swings +-28 degrees; the knee bends while the leg swings forward; the foot
    // stays roughly flat. Left and right are half a cycle apart.
    for (int side = 0; side < 2; ++side) {
        float offset = side == 0 ? 0.0f : kTwoPi / 2.0f;
        int thigh = side == 0 ? kThighL : kThighR, shin = side == 0 ? kShinL : kShinR,
            foot = side == 0 ? kFootL : kFootR;
        auto knee = [offset](float ph) {
            float s = std::sin(ph + offset + 1.2f);
            return 6.0f + 50.0f * std::max(0.0f, s) * std::max(0.0f, s);
        };
        // Positive rotation about X swings a hanging limb backward (-Z); forward is negative.
        rotations(thigh,
                  [offset](float ph) { return glm::vec3(-28.0f * std::sin(ph + offset), 0.0f, 0.0f); });
        rotations(shin, [knee](float ph) { return glm::vec3(knee(ph), 0.0f, 0.0f); });
        rotations(foot, [offset, knee](float ph) {
            return glm::vec3(28.0f * std::sin(ph + offset) - knee(ph) + 6.0f, 0.0f, 0.0f);
        });
    }
    // Arms swing against the legs, the elbows bend a little more on the forward swing.
    for (int side = 0; side < 2; ++side) {
        float offset = side == 0 ? kTwoPi / 2.0f : 0.0f;
        float out = side == 0 ? 1.0f : -1.0f;  // a little away from the body
        int upper = side == 0 ? kUpperArmL : kUpperArmR, fore = side == 0 ? kForearmL : kForearmR;
        rotations(upper, [offset, out](float ph) {
            return glm::vec3(-22.0f * std::sin(ph + offset), 0.0f, 6.0f * out);
        });
        rotations(fore, [offset](float ph) {
            return glm::vec3(-18.0f - 14.0f * std::max(0.0f, std::sin(ph + offset)), 0.0f, 0.0f);
        });
    }
    return clip.finish("walk");
}

Json idleClip(GltfBuilder& gltf) {
    ClipBuilder clip{gltf};
    // Breathing: the chest swells by 2 % and back, linear keys over 2 s.
    clip.add(kFirstJointNode + kChest, "scale", "LINEAR", {0.0f, 1.0f, 2.0f},
             {{1, 1, 1, 0}, {1.02f, 1.02f, 1.03f, 0}, {1, 1, 1, 0}}, true);
    // Looking around: the head snaps between three directions (step keys hold each one).
    clip.add(kFirstJointNode + kHead, "rotation", "STEP", {0.0f, 0.6f, 1.3f, 2.0f},
             {xyzw(euler(0, 25, 0)), xyzw(euler(-5, 0, 0)), xyzw(euler(0, -25, 0)), xyzw(euler(0, 25, 0))},
             false);
    // Arms hang a little away from the body.
    clip.add(kFirstJointNode + kUpperArmL, "rotation", "LINEAR", {0.0f, 2.0f},
             {xyzw(euler(0, 0, 5)), xyzw(euler(0, 0, 5))}, false);
    clip.add(kFirstJointNode + kUpperArmR, "rotation", "LINEAR", {0.0f, 2.0f},
             {xyzw(euler(0, 0, -5)), xyzw(euler(0, 0, -5))}, false);
    return clip.finish("idle");
}

Json material(const char* name, glm::vec3 color, int texture = -1) {
    Json factor = decimals(color);
    factor.push_back(1.0);
    Json pbr = {{"baseColorFactor", factor}, {"metallicFactor", 0.0}, {"roughnessFactor", 0.8}};
    if (texture >= 0) pbr["baseColorTexture"] = {{"index", texture}};
    return {{"name", name}, {"pbrMetallicRoughness", pbr}};
}

}  // namespace

GeneratedModel makeCharacter() {
    GltfBuilder gltf("character.bin");
    auto bind = bindPositions();

    // Materials: a textured suit, skin, glowing visor (HDR through KHR_materials_emissive_strength,
    // because the core emissiveFactor stops at 1), dark boots.
    int fabric = gltf.addTexture(gltf.addImage("../textures/suit_fabric.png"));
    gltf.addMaterial(material("suit", {0.24f, 0.42f, 0.7f}, fabric));
    gltf.addMaterial(material("skin", {0.86f, 0.66f, 0.5f}));
    Json visor = material("visor", {0.04f, 0.04f, 0.05f});
    visor["emissiveFactor"] = {0.125, 0.625, 1.0};
    visor["extensions"] = {{"KHR_materials_emissive_strength", {{"emissiveStrength", 2.5}}}};
    gltf.addMaterial(visor);
    gltf.useExtension("KHR_materials_emissive_strength");
    gltf.addMaterial(material("boots", {0.12f, 0.1f, 0.09f}));

    // One primitive per material.
    std::array<Primitive, kMaterialCount> prims;
    for (const Part& part : kParts) addPart(prims[part.material], part, bind);
    Json primitives = Json::array();
    for (int m = 0; m < kMaterialCount; ++m) {
        Primitive& p = prims[std::size_t(m)];
        // glTF's texture coordinates start at the top of the image; MeshData's (GL's) at the bottom.
        std::vector<glm::vec2> uvs;
        for (const glm::vec2& uv : p.mesh.uvs) uvs.emplace_back(uv.x, 1.0f - uv.y);
        Json attributes = {{"POSITION", gltf.addPositions(p.mesh.positions)},
                           {"NORMAL", gltf.addVec3(p.mesh.normals)},
                           {"TEXCOORD_0", gltf.addVec2(uvs)},
                           {"JOINTS_0", gltf.addJoints8(p.joints)},
                           {"WEIGHTS_0", gltf.addWeights8(p.weights)}};
        primitives.push_back(
            {{"attributes", attributes}, {"indices", gltf.addIndices16(p.mesh.indices)}, {"material", m}});
    }
    gltf.addMesh({{"name", "character"}, {"primitives", primitives}});

    // Nodes: 0 holds the skinned mesh, 1 is the armature, 2.. are the joints in kJoints order.
    gltf.addNode({{"name", "character"}, {"mesh", 0}, {"skin", 0}});
    gltf.addNode({{"name", "armature"}, {"children", {kFirstJointNode + kHips}}});
    std::vector<glm::mat4> inverseBind;
    Json jointNodes = Json::array();
    for (int j = 0; j < kJointCount; ++j) {
        const glm::vec3& t = kJoints[j].offset;
        gltf.addNode({{"name", kJoints[j].name}, {"translation", decimals(t)}});
        inverseBind.push_back(glm::translate(glm::mat4(1.0f), -bind[std::size_t(j)]));
        jointNodes.push_back(kFirstJointNode + j);
    }
    for (int j = 0; j < kJointCount; ++j) {
        Json children = Json::array();
        for (int c = 0; c < kJointCount; ++c)
            if (kJoints[c].parent == j) children.push_back(kFirstJointNode + c);
        if (!children.empty()) gltf.node(kFirstJointNode + j)["children"] = children;
    }
    gltf.addSkin({{"name", "skeleton"},
                  {"inverseBindMatrices", gltf.addMat4(inverseBind)},
                  {"skeleton", kFirstJointNode + kHips},
                  {"joints", jointNodes}});
    gltf.setSceneRoots({0, 1});
    gltf.addAnimation(walkClip(gltf, bind));
    gltf.addAnimation(idleClip(gltf));
    return {gltf.gltfText(), gltf.binBytes()};
}

}  // namespace fx::assetgen
