// The glTF model builder: the whole build, textures, materials and the node hierarchy.
#include "scene/gltf_model_builder.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "scene/gltf_accessor_reader.hpp"

namespace fx::gltf_detail {

Result<GltfModel> ModelBuilder::build() {
    readTextures();
    readMaterials();
    for (std::size_t i = 0; i < m_.meshes.size(); ++i) {
        if (auto s = readMesh(i); !s) return Error{s.error()};
    }
    if (auto s = readNodes(); !s) return Error{s.error()};
    for (std::size_t i = 0; i < m_.skins.size(); ++i) {
        if (auto s = readSkin(i); !s) return Error{s.error()};
    }
    checkSkinnedNodes();
    for (std::size_t i = 0; i < m_.animations.size(); ++i) {
        if (auto s = readAnimation(i); !s) return Error{s.error()};
    }
    if (!m_.cameras.empty())
        warn(cat(m_.cameras.size(), " camera(s) ignored: the scene file places the camera"));
    if (!m_.lights.empty()) warn(cat(m_.lights.size(), " light(s) ignored: the scene file lists the lights"));
    return std::move(model_);
}

void ModelBuilder::readTextures() {
    for (std::size_t t = 0; t < m_.textures.size(); ++t) {
        ModelTexture texture;
        int source = m_.textures[t].source;
        if (source >= 0 && static_cast<std::size_t>(source) < m_.images.size()) {
            const tinygltf::Image& image = m_.images[static_cast<std::size_t>(source)];
            texture.mimeType = image.mimeType;
            bool external = !image.uri.empty() && image.uri.rfind("data:", 0) != 0;
            if (external) {
                texture.file = (baseDir_ / fs::path(image.uri)).lexically_normal();
                if (!images_.bytes.count(source))
                    warn(cat("texture ", t, ": cannot read ", texture.file.string()));
            } else if (auto it = images_.bytes.find(source); it != images_.bytes.end()) {
                texture.encoded = it->second;
            }
        } else {
            warn(cat("texture ", t, " has no image"));
        }
        model_.textures.push_back(std::move(texture));
    }
}

int ModelBuilder::textureIndex(int index, const std::string& what) {
    if (index < 0) return -1;
    if (static_cast<std::size_t>(index) >= model_.textures.size() ||
        model_.textures[std::size_t(index)].empty()) {
        warn(cat(what, ": texture ", index, " is missing; drawn without it"));
        return -1;
    }
    return index;
}

void ModelBuilder::readMaterials() {
    for (std::size_t i = 0; i < m_.materials.size(); ++i) {
        const tinygltf::Material& src = m_.materials[i];
        std::string what = named("material", i, src.name);
        ModelMaterial material;
        material.name = src.name;
        const auto& factor = src.pbrMetallicRoughness.baseColorFactor;
        for (std::size_t c = 0; c < 4 && c < factor.size(); ++c)
            material.baseColor[int(c)] = float(factor[c]);
        material.baseColorTexture = textureIndex(src.pbrMetallicRoughness.baseColorTexture.index, what);
        for (std::size_t c = 0; c < 3 && c < src.emissiveFactor.size(); ++c)
            material.emissive[int(c)] = float(src.emissiveFactor[c]);
        if (auto ext = src.extensions.find("KHR_materials_emissive_strength"); ext != src.extensions.end()) {
            const tinygltf::Value& strength = ext->second.Get("emissiveStrength");
            if (strength.IsNumber()) material.emissive *= float(strength.GetNumberAsDouble());
        }
        material.emissiveTexture = textureIndex(src.emissiveTexture.index, what);
        material.doubleSided = src.doubleSided;
        model_.materials.push_back(material);
    }
}

Status ModelBuilder::readNodes() {
    const std::size_t count = m_.nodes.size();
    model_.nodes.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        const tinygltf::Node& src = m_.nodes[i];
        ModelNode& node = model_.nodes[i];
        std::string what = named("node", i, src.name);
        node.name = src.name;
        if (src.translation.size() == 3)
            node.rest.translation = {float(src.translation[0]), float(src.translation[1]),
                                     float(src.translation[2])};
        if (src.rotation.size() == 4)
            node.rest.rotation = toQuat({float(src.rotation[0]), float(src.rotation[1]),
                                         float(src.rotation[2]), float(src.rotation[3])});
        if (src.scale.size() == 3)
            node.rest.scale = {float(src.scale[0]), float(src.scale[1]), float(src.scale[2])};
        if (src.matrix.size() == 16) {
            node.hasMatrix = true;
            for (int k = 0; k < 16; ++k) glm::value_ptr(node.matrix)[k] = float(src.matrix[std::size_t(k)]);
        }
        if (src.mesh >= 0) {
            if (static_cast<std::size_t>(src.mesh) >= model_.meshes.size())
                return Error{cat(what, ": mesh ", src.mesh, " does not exist")};
            node.mesh = src.mesh;
        }
        if (src.skin >= 0) {
            if (static_cast<std::size_t>(src.skin) >= m_.skins.size())
                return Error{cat(what, ": skin ", src.skin, " does not exist")};
            node.skin = src.skin;
        }
        for (int child : src.children) {
            if (child < 0 || static_cast<std::size_t>(child) >= count)
                return Error{cat(what, ": child ", child, " does not exist")};
            node.children.push_back(child);
        }
    }
    for (std::size_t i = 0; i < count; ++i) {
        for (int child : model_.nodes[i].children) {
            ModelNode& c = model_.nodes[static_cast<std::size_t>(child)];
            if (c.parent >= 0 || child == int(i))
                return Error{cat(named("node", std::size_t(child), c.name), " has more than one parent")};
            c.parent = static_cast<int>(i);
        }
    }
    // A cycle leaves nodes that never reach a root.
    for (std::size_t i = 0; i < count; ++i) {
        std::size_t steps = 0;
        for (int p = model_.nodes[i].parent; p >= 0; p = model_.nodes[std::size_t(p)].parent) {
            if (++steps > count)
                return Error{cat(named("node", i, model_.nodes[i].name), " is part of a cycle")};
        }
    }
    int sceneIndex = m_.defaultScene >= 0 ? m_.defaultScene : (m_.scenes.empty() ? -1 : 0);
    if (sceneIndex >= 0 && static_cast<std::size_t>(sceneIndex) < m_.scenes.size()) {
        for (int root : m_.scenes[std::size_t(sceneIndex)].nodes) {
            if (root >= 0 && static_cast<std::size_t>(root) < count) model_.roots.push_back(root);
        }
    } else {
        for (std::size_t i = 0; i < count; ++i)
            if (model_.nodes[i].parent < 0) model_.roots.push_back(int(i));
    }
    return Status::success();
}

}  // namespace fx::gltf_detail
