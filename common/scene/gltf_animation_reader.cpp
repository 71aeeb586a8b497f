// The glTF model builder: skins and animation clips.
#include "scene/gltf_model_builder.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "scene/gltf_accessor_reader.hpp"

namespace fx::gltf_detail {

Status ModelBuilder::readSkin(std::size_t index) {
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
        auto r = AccessorReader::open(m_, src.inverseBindMatrices, what + " inverseBindMatrices",
                                      {16, {kFloat}, "float MAT4"});
        if (!r) return Error{r.error()};
        if (r->count() < skin.joints.size())
            return Error{
                cat(what, ": ", r->count(), " inverse bind matrices for ", skin.joints.size(), " joints")};
        for (std::size_t j = 0; j < skin.joints.size(); ++j) {
            for (int k = 0; k < 16; ++k) glm::value_ptr(skin.inverseBindMatrices[j])[k] = r->real(j, k);
        }
    }
    model_.skins.push_back(std::move(skin));
    return Status::success();
}

void ModelBuilder::checkSkinnedNodes() {
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
                warn(cat(named("node", i, node.name), ": joint ", largest, " is beyond the skin's ", joints,
                         " joints; such influences count as weight 0"));
        }
    }
}

Status ModelBuilder::readAnimation(std::size_t index) {
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
        auto input =
            AccessorReader::open(m_, sampler.input, where + " input", {1, {kFloat}, "float scalars"});
        if (!input) return Error{input.error()};
        bool rotation = channel.property == AnimatedProperty::rotation;
        auto output = AccessorReader::open(m_, sampler.output, where + " output",
                                           {rotation ? 4 : 3, {}, rotation ? "VEC4 for rotation" : "VEC3"});
        if (!output) return Error{output.error()};
        std::size_t keys = input->count();
        std::size_t perKey = channel.interpolation == Interpolation::cubicSpline ? 3 : 1;
        std::size_t values = 0;
        if (!multiplyFits(keys, perKey, values) || output->count() != values)
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

}  // namespace fx::gltf_detail
