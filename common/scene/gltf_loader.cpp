#include "scene/gltf_loader.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <optional>

#include <tiny_gltf.h>
#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "base/log.hpp"
#include "scene/gltf_accessor_reader.hpp"

namespace fx {
namespace {

namespace fs = std::filesystem;
using namespace gltf_detail;

constexpr int kTriangles = 4, kTriangleStrip = 5, kTriangleFan = 6;

// Encoded image bytes, captured instead of decoded: the GL layer decodes what it uploads.
struct CapturedImages {
    std::map<int, std::vector<unsigned char>> bytes;
};

bool captureImage(tinygltf::Image* image, const int index, std::string*, std::string*, int, int,
                  const unsigned char* bytes, int size, void* user) {
    auto* captured = static_cast<CapturedImages*>(user);
    if (bytes && size > 0) captured->bytes[index].assign(bytes, bytes + size);
    image->width = image->height = image->component = -1;  // not decoded
    return true;
}

// Collects what goes into one model, with the file name on every message.
class ModelBuilder {
public:
    ModelBuilder(const tinygltf::Model& m, const fs::path& file, const fs::path& baseDir,
                 CapturedImages& images)
        : m_(m), baseDir_(baseDir), images_(images) {
        model_.file = file;
    }

    Result<GltfModel> build() {
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
        if (!m_.lights.empty())
            warn(cat(m_.lights.size(), " light(s) ignored: the scene file lists the lights"));
        return std::move(model_);
    }

private:
    const tinygltf::Model& m_;
    fs::path baseDir_;
    CapturedImages& images_;
    GltfModel model_;

    void warn(std::string message) { model_.warnings.push_back(std::move(message)); }

    static std::string named(const char* kind, std::size_t index, const std::string& name) {
        return name.empty() ? cat(kind, " ", index) : cat(kind, " '", name, "'");
    }

    void readTextures() {
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

    int textureIndex(int index, const std::string& what) {
        if (index < 0) return -1;
        if (static_cast<std::size_t>(index) >= model_.textures.size() ||
            model_.textures[std::size_t(index)].empty()) {
            warn(cat(what, ": texture ", index, " is missing; drawn without it"));
            return -1;
        }
        return index;
    }

    void readMaterials() {
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
            if (auto ext = src.extensions.find("KHR_materials_emissive_strength");
                ext != src.extensions.end()) {
                const tinygltf::Value& strength = ext->second.Get("emissiveStrength");
                if (strength.IsNumber()) material.emissive *= float(strength.GetNumberAsDouble());
            }
            material.emissiveTexture = textureIndex(src.emissiveTexture.index, what);
            material.doubleSided = src.doubleSided;
            model_.materials.push_back(material);
        }
    }

    Status readIndices(const tinygltf::Primitive& p, std::size_t vertices, const std::string& what,
                       std::vector<std::uint32_t>& out) {
        std::vector<std::uint32_t> raw;
        if (p.indices >= 0) {
            auto r = AccessorReader::open(m_, p.indices, what + " indices");
            if (!r) return Error{r.error()};
            int type = r->componentType();
            if (r->components() != 1 ||
                (type != kUnsignedByte && type != kUnsignedShort && type != kUnsignedInt))
                return Error{cat(what, ": indices must be unsigned 8-, 16- or 32-bit scalars")};
            raw.resize(r->count());
            for (std::size_t i = 0; i < raw.size(); ++i) {
                raw[i] = r->whole(i, 0);
                if (raw[i] >= vertices)
                    return Error{cat(what, ": index ", raw[i], " is beyond the ", vertices, " vertices")};
            }
        } else {
            raw.resize(vertices);
            for (std::size_t i = 0; i < vertices; ++i) raw[i] = static_cast<std::uint32_t>(i);
        }
        int mode = p.mode < 0 ? kTriangles : p.mode;
        out.clear();
        if (mode == kTriangles) {
            out.assign(raw.begin(), raw.end() - static_cast<std::ptrdiff_t>(raw.size() % 3));
        } else if (mode == kTriangleStrip) {
            for (std::size_t i = 2; i < raw.size(); ++i) {
                bool even = (i % 2) == 0;
                out.insert(out.end(), {raw[i - 2], even ? raw[i - 1] : raw[i], even ? raw[i] : raw[i - 1]});
            }
        } else if (mode == kTriangleFan) {
            for (std::size_t i = 2; i < raw.size(); ++i) out.insert(out.end(), {raw[0], raw[i - 1], raw[i]});
        }
        return Status::success();
    }

    Status readMesh(std::size_t meshIndex) {
        const tinygltf::Mesh& src = m_.meshes[meshIndex];
        ModelMesh mesh;
        mesh.name = src.name;
        for (std::size_t pi = 0; pi < src.primitives.size(); ++pi) {
            const tinygltf::Primitive& p = src.primitives[pi];
            std::string what = cat(named("mesh", meshIndex, src.name), " primitive ", pi);
            int mode = p.mode < 0 ? kTriangles : p.mode;
            if (mode != kTriangles && mode != kTriangleStrip && mode != kTriangleFan) {
                warn(cat(what, ": points and lines are not drawn; skipped"));
                continue;
            }
            if (!p.targets.empty()) warn(cat(what, ": morph targets are ignored"));
            auto attribute = [&](const char* name) {
                auto it = p.attributes.find(name);
                return it == p.attributes.end() ? -1 : it->second;
            };
            int positionIndex = attribute("POSITION");
            if (positionIndex < 0) return Error{cat(what, ": has no POSITION attribute")};
            auto positions = AccessorReader::open(m_, positionIndex, what + " POSITION");
            if (!positions) return Error{positions.error()};
            if (positions->components() != 3) return Error{cat(what, ": POSITION must be VEC3")};
            std::size_t n = positions->count();

            ModelPrimitive prim;
            prim.material = p.material;
            if (p.material >= 0 && static_cast<std::size_t>(p.material) >= model_.materials.size()) {
                warn(
                    cat(what, ": material ", p.material, " does not exist; drawn with the default material"));
                prim.material = -1;
            }
            MeshData& data = prim.mesh;
            data.positions.resize(n);
            for (std::size_t i = 0; i < n; ++i) {
                glm::vec3 v(positions->vec(i));
                if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
                    return Error{cat(what, ": position ", i, " is not finite")};
                data.positions[i] = v;
            }
            // Optional attributes must match the vertex count.
            auto openSized = [&](const char* name, int components) -> Result<std::optional<AccessorReader>> {
                int index = attribute(name);
                if (index < 0) return std::optional<AccessorReader>{};
                auto r = AccessorReader::open(m_, index, cat(what, " ", name));
                if (!r) return Error{r.error()};
                if (r->count() != n)
                    return Error{
                        cat(what, ": ", name, " has ", r->count(), " elements for ", n, " vertices")};
                if (r->components() != components)
                    return Error{cat(what, ": ", name, " must have ", components, " components")};
                return std::optional<AccessorReader>{*r};
            };
            auto normals = openSized("NORMAL", 3);
            if (!normals) return Error{normals.error()};
            auto uvs = openSized("TEXCOORD_0", 2);
            if (!uvs) return Error{uvs.error()};
            auto joints = openSized("JOINTS_0", 4);
            if (!joints) return Error{joints.error()};
            auto weights = openSized("WEIGHTS_0", 4);
            if (!weights) return Error{weights.error()};

            data.uvs.assign(n, glm::vec2(0.0f));
            if (*uvs) {
                // glTF's v runs down from the top of the image; fxlab's (GL's) runs up from the bottom row.
                for (std::size_t i = 0; i < n; ++i)
                    data.uvs[i] = {(*uvs)->real(i, 0), 1.0f - (*uvs)->real(i, 1)};
            }
            if (auto s = readIndices(p, n, what, data.indices); !s) return s;
            if (*normals) {
                data.normals.resize(n);
                for (std::size_t i = 0; i < n; ++i) data.normals[i] = glm::vec3((*normals)->vec(i));
            } else {
                computeNormals(data);
                prim.generatedNormals = true;
            }
            if (*joints && *weights) {
                int type = (*joints)->componentType();
                if (type != kUnsignedByte && type != kUnsignedShort)
                    return Error{cat(what, ": JOINTS_0 must be unsigned 8- or 16-bit")};
                prim.influences.resize(n);
                for (std::size_t i = 0; i < n; ++i) {
                    JointInfluence& inf = prim.influences[i];
                    for (int c = 0; c < 4; ++c)
                        inf.joints[c] = static_cast<std::uint16_t>((*joints)->whole(i, c));
                    inf.weights = (*weights)->vec(i);
                }
            } else if (*joints || *weights) {
                warn(cat(what, ": JOINTS_0 without WEIGHTS_0 (or the reverse); drawn unskinned"));
            }
            mesh.primitives.push_back(std::move(prim));
        }
        model_.meshes.push_back(std::move(mesh));
        return Status::success();
    }

    Status readNodes() {
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
                for (int k = 0; k < 16; ++k)
                    glm::value_ptr(node.matrix)[k] = float(src.matrix[std::size_t(k)]);
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

    Status readSkin(std::size_t index) {
        const tinygltf::Skin& src = m_.skins[index];
        std::string what = named("skin", index, src.name);
        Skin skin;
        skin.name = src.name;
        for (int joint : src.joints) {
            if (joint < 0 || static_cast<std::size_t>(joint) >= model_.nodes.size())
                return Error{cat(what, ": joint node ", joint, " does not exist")};
            skin.joints.push_back(joint);
        }
        skin.inverseBindMatrices.assign(skin.joints.size(), glm::mat4(1.0f));
        if (src.inverseBindMatrices >= 0) {
            auto r = AccessorReader::open(m_, src.inverseBindMatrices, what + " inverseBindMatrices");
            if (!r) return Error{r.error()};
            if (r->components() != 16 || r->componentType() != kFloat)
                return Error{cat(what, ": inverseBindMatrices must be float MAT4")};
            if (r->count() < skin.joints.size())
                return Error{cat(what, ": ", r->count(), " inverse bind matrices for ", skin.joints.size(),
                                 " joints")};
            for (std::size_t j = 0; j < skin.joints.size(); ++j) {
                for (int k = 0; k < 16; ++k) glm::value_ptr(skin.inverseBindMatrices[j])[k] = r->real(j, k);
            }
        }
        model_.skins.push_back(std::move(skin));
        return Status::success();
    }

    void checkSkinnedNodes() {
        for (std::size_t i = 0; i < model_.nodes.size(); ++i) {
            const ModelNode& node = model_.nodes[i];
            if (node.mesh < 0) continue;
            const ModelMesh& mesh = model_.meshes[std::size_t(node.mesh)];
            std::size_t joints = node.skin >= 0 ? model_.skins[std::size_t(node.skin)].jointCount() : 0;
            for (const ModelPrimitive& p : mesh.primitives) {
                if (!p.skinned()) continue;
                if (node.skin < 0) {
                    warn(cat(named("node", i, node.name),
                             ": its mesh has joints but the node has no skin; drawn unskinned"));
                    break;
                }
                std::uint32_t largest = 0;
                for (const JointInfluence& inf : p.influences)
                    for (int c = 0; c < 4; ++c)
                        if (inf.weights[c] > 0.0f) largest = std::max<std::uint32_t>(largest, inf.joints[c]);
                if (largest >= joints)
                    warn(cat(named("node", i, node.name), ": joint ", largest, " is beyond the skin's ",
                             joints, " joints; such influences count as weight 0"));
            }
        }
    }

    Status readAnimation(std::size_t index) {
        const tinygltf::Animation& src = m_.animations[index];
        AnimationClip clip;
        clip.name = src.name.empty() ? cat("animation ", index) : src.name;
        std::string what = cat("animation '", clip.name, "'");
        for (std::size_t ci = 0; ci < src.channels.size(); ++ci) {
            const tinygltf::AnimationChannel& ch = src.channels[ci];
            std::string where = cat(what, " channel ", ci);
            AnimationChannel channel;
            if (ch.target_path == "translation") {
                channel.property = AnimatedProperty::translation;
            } else if (ch.target_path == "rotation") {
                channel.property = AnimatedProperty::rotation;
            } else if (ch.target_path == "scale") {
                channel.property = AnimatedProperty::scale;
            } else {
                warn(cat(where, ": '", ch.target_path, "' is not animated by fxlab; skipped"));
                continue;
            }
            if (ch.target_node < 0 || static_cast<std::size_t>(ch.target_node) >= model_.nodes.size())
                return Error{cat(where, ": target node ", ch.target_node, " does not exist")};
            channel.node = ch.target_node;
            if (model_.nodes[std::size_t(ch.target_node)].hasMatrix)
                warn(cat(where, ": its node has a matrix, which animation cannot change"));
            if (ch.sampler < 0 || static_cast<std::size_t>(ch.sampler) >= src.samplers.size())
                return Error{cat(where, ": sampler ", ch.sampler, " does not exist")};
            const tinygltf::AnimationSampler& sampler = src.samplers[std::size_t(ch.sampler)];
            if (sampler.interpolation == "STEP") {
                channel.interpolation = Interpolation::step;
            } else if (sampler.interpolation == "CUBICSPLINE") {
                channel.interpolation = Interpolation::cubicSpline;
            } else {
                channel.interpolation = Interpolation::linear;  // the default, and "LINEAR"
            }
            auto input = AccessorReader::open(m_, sampler.input, where + " input");
            if (!input) return Error{input.error()};
            auto output = AccessorReader::open(m_, sampler.output, where + " output");
            if (!output) return Error{output.error()};
            int needed = channel.property == AnimatedProperty::rotation ? 4 : 3;
            if (input->components() != 1) return Error{cat(where, ": key times must be scalars")};
            if (output->components() != needed)
                return Error{cat(where, ": values must have ", needed, " components for ", ch.target_path)};
            std::size_t keys = input->count();
            std::size_t perKey = channel.interpolation == Interpolation::cubicSpline ? 3 : 1;
            if (output->count() != keys * perKey)
                return Error{cat(where, ": ", output->count(), " values for ", keys, " keys")};
            for (std::size_t k = 0; k < keys; ++k) {
                float t = input->real(k, 0);
                if (!std::isfinite(t) || t < 0.0f)
                    return Error{cat(where, ": key time ", k, " is not a finite time >= 0")};
                if (k > 0 && t < channel.times.back())
                    return Error{cat(where, ": key times decrease at key ", k)};
                channel.times.push_back(t);
            }
            for (std::size_t v = 0; v < output->count(); ++v) {
                glm::vec4 value = output->vec(v);
                if (!std::isfinite(value.x) || !std::isfinite(value.y) || !std::isfinite(value.z) ||
                    !std::isfinite(value.w))
                    return Error{cat(where, ": value ", v, " is not finite")};
                channel.values.push_back(value);
            }
            if (!channel.times.empty()) clip.duration = std::max(clip.duration, channel.times.back());
            clip.channels.push_back(std::move(channel));
        }
        model_.clips.push_back(std::move(clip));
        return Status::success();
    }
};

Result<GltfModel> finish(bool ok, const tinygltf::Model& m, const std::string& err, const std::string& warn,
                         const fs::path& file, const fs::path& baseDir, CapturedImages& images) {
    if (!ok) {
        std::string message = err.empty() ? "tinygltf could not read it" : err;
        while (!message.empty() && message.back() == '\n') message.pop_back();
        return Error{cat(file.string(), ": ", message)};
    }
    auto model = ModelBuilder(m, file, baseDir, images).build();
    if (!model) return Error{cat(file.string(), ": ", model.error())};
    // tinygltf's own warnings, one per line.
    std::size_t start = 0;
    while (start < warn.size()) {
        std::size_t end = warn.find('\n', start);
        if (end == std::string::npos) end = warn.size();
        if (end > start) model->warnings.push_back(warn.substr(start, end - start));
        start = end + 1;
    }
    for (const auto& w : model->warnings) log::warning(file.filename().string(), ": ", w);
    return model;
}

}  // namespace

const AnimationClip* GltfModel::findClip(const std::string& name) const {
    for (const auto& clip : clips)
        if (clip.name == name) return &clip;
    return nullptr;
}

std::size_t GltfModel::vertexCount() const {
    std::size_t n = 0;
    for (const auto& mesh : meshes)
        for (const auto& p : mesh.primitives) n += p.mesh.vertexCount();
    return n;
}

std::size_t GltfModel::triangleCount() const {
    std::size_t n = 0;
    for (const auto& mesh : meshes)
        for (const auto& p : mesh.primitives) n += p.mesh.triangleCount();
    return n;
}

std::vector<int> GltfModel::meshNodes() const {
    std::vector<int> result;
    for (std::size_t i = 0; i < nodes.size(); ++i)
        if (nodes[i].mesh >= 0) result.push_back(static_cast<int>(i));
    return result;
}

void computeNormals(MeshData& mesh) {
    std::vector<glm::vec3> sum(mesh.positions.size(), glm::vec3(0.0f));
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        std::uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
        if (a >= sum.size() || b >= sum.size() || c >= sum.size()) continue;
        // The cross product's length is twice the area, so big triangles weigh more.
        glm::vec3 n =
            glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
        sum[a] += n;
        sum[b] += n;
        sum[c] += n;
    }
    mesh.normals.resize(mesh.positions.size());
    for (std::size_t i = 0; i < sum.size(); ++i) {
        float length = glm::length(sum[i]);
        mesh.normals[i] = length > 1e-20f ? sum[i] / length : glm::vec3(0.0f, 1.0f, 0.0f);
    }
}

Result<GltfModel> loadGltf(const fs::path& file) {
    std::error_code ec;
    if (!fs::is_regular_file(file, ec)) return Error{cat(file.string(), ": no such file")};
    tinygltf::TinyGLTF loader;
    CapturedImages images;
    loader.SetImageLoader(&captureImage, &images);
    tinygltf::Model m;
    std::string err, warn;
    bool binary = file.extension() == ".glb" || file.extension() == ".GLB";
    bool ok = binary ? loader.LoadBinaryFromFile(&m, &err, &warn, file.string())
                     : loader.LoadASCIIFromFile(&m, &err, &warn, file.string());
    return finish(ok, m, err, warn, file, file.parent_path(), images);
}

Result<GltfModel> parseGltf(const std::string& json, const fs::path& baseDir, const fs::path& nominalFile) {
    tinygltf::TinyGLTF loader;
    CapturedImages images;
    loader.SetImageLoader(&captureImage, &images);
    tinygltf::Model m;
    std::string err, warn;
    bool ok = loader.LoadASCIIFromString(&m, &err, &warn, json.c_str(),
                                         static_cast<unsigned int>(json.size()), baseDir.string());
    return finish(ok, m, err, warn, nominalFile, baseDir, images);
}

}  // namespace fx
