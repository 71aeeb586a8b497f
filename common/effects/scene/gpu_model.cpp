#include "effects/scene/gpu_model.hpp"

#include <glm/gtc/type_ptr.hpp>

#include "base/log.hpp"
#include "effects/scene/scene_meshes.hpp"
#include "gl/device_limits.hpp"

namespace fx {
namespace {

GLuint textureFor(const GltfModel& model, int index, MaterialTextures& textures) {
    if (index < 0 || static_cast<std::size_t>(index) >= model.textures.size()) return textures.white();
    const ModelTexture& t = model.textures[static_cast<std::size_t>(index)];
    if (!t.file.empty()) return textures.file(t.file);
    if (!t.encoded.empty()) return textures.encoded(cat(model.file.string(), "#texture", index), t.encoded);
    return textures.white();
}

// A skin's joint matrices are one storage block: a skin with more joints than the device's block holds
// is drawn unskinned, in its bind pose, with a warning (docs/reliability.md, "Budgets").
bool jointsFit(const GltfModel& model, int skin, const std::string& label) {
    const gl::DeviceLimits device = gl::queryDeviceLimits();
    const std::size_t joints = model.skins[static_cast<std::size_t>(skin)].joints.size();
    Status fits = gl::checkStorageBlock(device, joints, sizeof(glm::mat4),
                                        cat(label, ": skin ", skin, "'s joint matrices"));
    if (!fits) log::warning(fits.error(), "; drawn unskinned, in its bind pose");
    return fits.ok();
}

}  // namespace

GpuModel::GpuModel(std::shared_ptr<const GltfModel> model, MaterialTextures& textures, std::string_view label)
    : model_(std::move(model)) {
    const GltfModel& m = *model_;
    defaultMaterial_.baseColorTexture = defaultMaterial_.emissiveTexture = textures.white();
    for (const ModelMaterial& material : m.materials) {
        materials_.push_back({glm::vec3(material.baseColor), material.emissive,
                              textureFor(m, material.baseColorTexture, textures),
                              textureFor(m, material.emissiveTexture, textures)});
    }
    for (int node : m.meshNodes()) {
        const ModelNode& n = m.nodes[static_cast<std::size_t>(node)];
        const ModelMesh& mesh = m.meshes[static_cast<std::size_t>(n.mesh)];
        Instance instance;
        instance.node = node;
        instance.joints =
            JointMatrixBuffer(cat(label, ".", n.name.empty() ? cat("node ", node) : n.name, ".joints"));
        for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
            const ModelPrimitive& prim = mesh.primitives[p];
            std::string partLabel =
                cat(label, ".", mesh.name.empty() ? cat("mesh ", n.mesh) : mesh.name, "[", p, "]");
            Part part;
            part.material = prim.material;
            // A mesh with joints is skinned only on a node that has a skin (the loader warned otherwise).
            part.skinned = prim.skinned() && n.skin >= 0 && jointsFit(m, n.skin, partLabel);
            if (part.skinned) {
                part.skinnedMesh = SkinnedMesh(prim.mesh, prim.influences, partLabel);
                if (part.skinnedMesh.unweightedVertices() > 0)
                    log::warning(partLabel, ": ", part.skinnedMesh.unweightedVertices(),
                                 " vertices have no joint weight; they keep the bind pose");
                instance.skinned = true;
            } else {
                part.staticMesh = GpuMesh(prim.mesh, partLabel);
            }
            instance.parts.push_back(std::move(part));
        }
        instances_.push_back(std::move(instance));
    }
    animate(nullptr, 0.0f, nullptr);
}

void GpuModel::animate(const AnimationClip* clip, float clipSeconds, const GpuSkinning* skinning) {
    const GltfModel& m = *model_;
    std::vector<NodeTransform> pose = restPose(m.nodes);
    if (clip) applyClip(*clip, clipSeconds, pose);
    world_ = worldMatrices(m.nodes, pose);
    for (Instance& instance : instances_) {
        if (!instance.skinned) continue;
        const ModelNode& node = m.nodes[static_cast<std::size_t>(instance.node)];
        instance.jointMatrices = fx::jointMatrices(m.skins[static_cast<std::size_t>(node.skin)], world_,
                                                   world_[static_cast<std::size_t>(instance.node)]);
        instance.joints.upload(instance.jointMatrices);
        if (!skinning) continue;
        for (const Part& part : instance.parts)
            if (part.skinned) skinning->pose(part.skinnedMesh, instance.joints);
    }
}

void GpuModel::draw(GLuint program, const glm::mat4& objectModel, const ModelDrawStyle& style) const {
    glUseProgram(program);
    for (const Instance& instance : instances_) {
        glm::mat4 model = objectModel * world_[static_cast<std::size_t>(instance.node)];
        glProgramUniformMatrix4fv(program, glsl::kModelLocation, 1, GL_FALSE, glm::value_ptr(model));
        if (style.skinned == SkinnedDraw::source && instance.skinned)
            instance.joints.bind(glsl::kJointMatricesBinding);
        for (const Part& part : instance.parts) {
            const MaterialGpu& material =
                part.material >= 0 && static_cast<std::size_t>(part.material) < materials_.size()
                    ? materials_[static_cast<std::size_t>(part.material)]
                    : defaultMaterial_;
            if (style.setMaterial) {
                glm::vec3 base = material.baseColor * style.tint;
                glm::vec3 emissive = material.emissive + style.addedEmissive;
                glProgramUniform3fv(program, glsl::kBaseColorLocation, 1, glm::value_ptr(base));
                glProgramUniform3fv(program, glsl::kEmissiveLocation, 1, glm::value_ptr(emissive));
            }
            if (style.bindTextures) {
                glBindTextureUnit(glsl::kBaseColorTextureBinding, style.baseColorTexture
                                                                      ? style.baseColorTexture
                                                                      : material.baseColorTexture);
                glBindTextureUnit(glsl::kEmissiveTextureBinding, material.emissiveTexture);
            }
            if (!part.skinned) {
                part.staticMesh.draw();
            } else if (style.skinned == SkinnedDraw::source) {
                part.skinnedMesh.drawSource();
            } else {
                part.skinnedMesh.drawPosed();
            }
        }
    }
}

const std::vector<glm::mat4>& GpuModel::jointMatrices(int node) const {
    static const std::vector<glm::mat4> kNone;
    for (const Instance& instance : instances_)
        if (instance.node == node) return instance.jointMatrices;
    return kNone;
}

std::size_t GpuModel::skinnedMeshes() const {
    std::size_t n = 0;
    for (const Instance& instance : instances_)
        for (const Part& part : instance.parts) n += part.skinned ? 1 : 0;
    return n;
}

std::size_t GpuModel::unweightedVertices() const {
    std::size_t n = 0;
    for (const Instance& instance : instances_)
        for (const Part& part : instance.parts) n += part.skinned ? part.skinnedMesh.unweightedVertices() : 0;
    return n;
}

const SkinnedMesh* GpuModel::skinnedMesh(int node, std::size_t primitive) const {
    for (const Instance& instance : instances_) {
        if (instance.node != node || primitive >= instance.parts.size()) continue;
        const Part& part = instance.parts[primitive];
        return part.skinned ? &part.skinnedMesh : nullptr;
    }
    return nullptr;
}

}  // namespace fx
