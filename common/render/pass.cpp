#include "render/pass.hpp"

#include <algorithm>

#include "base/log.hpp"
#include "render/frame_graph.hpp"

namespace fx {

Pass::Pass(FrameGraph& graph, std::uint32_t index, std::string name, Body body)
    : graph_(graph), index_(index), name_(std::move(name)), body_(std::move(body)) {}

Pass& Pass::read(TextureHandle texture) {
    if (TextureAccess* a = addAccess(texture, true, false, TextureUsage::Sampled)) a->sampled = true;
    return *this;
}

Pass& Pass::readOtherLevel(TextureHandle texture) {
    if (TextureAccess* a = addAccess(texture, true, false, TextureUsage::Sampled)) {
        a->sampled = true;
        a->otherLevel = true;
    }
    return *this;
}

Pass& Pass::write(TextureHandle texture, TextureUsage usage) {
    addAccess(texture, false, true, usage);
    return *this;
}

Pass& Pass::modify(TextureHandle texture, TextureUsage usage) {
    addAccess(texture, true, true, usage);
    return *this;
}

TextureHandle Pass::create(std::string textureName, const TextureDesc& desc, TextureUsage usage) {
    TextureHandle texture = graph_.declareTexture(std::move(textureName), desc);
    write(texture, usage);
    return texture;
}

Pass& Pass::setState(const PassState& state) {
    state_ = state;
    return *this;
}

Pass& Pass::disable(std::string reason) {
    if (switch_ == PassSwitch::NotCalledFor) return *this;  // the scene's reason is the stronger one
    switch_ = PassSwitch::Disabled;
    switchReason_ = std::move(reason);
    return *this;
}

Pass& Pass::notCalledFor(std::string reason) {
    switch_ = PassSwitch::NotCalledFor;
    switchReason_ = std::move(reason);
    return *this;
}

Pass& Pass::needs(std::string requirement) {
    if (const std::string* reason = graph_.unmetReason(requirement)) notCalledFor(*reason);
    return *this;
}

Pass& Pass::joinGroup(const PassGroup& group) {
    group_ = group.id();
    if (!group.requirement().empty()) needs(group.requirement());
    return *this;
}

Pass& Pass::keepAlive() {
    keepAlive_ = true;
    return *this;
}

Pass& Pass::setTag(std::int64_t tag) {
    tag_ = tag;
    return *this;
}

Pass& Pass::setTaps(double perOutputPixel) {
    taps_ = std::max(perOutputPixel, 0.0);
    return *this;
}

TextureAccess* Pass::addAccess(TextureHandle texture, bool reads, bool writes, TextureUsage usage) {
    if (!graph_.owns(texture)) {
        declarationErrors_.push_back(
            cat("pass '", name_, "' uses a texture handle this frame's graph did not declare"));
        return nullptr;
    }
    if (writes && usage == TextureUsage::Sampled) {
        declarationErrors_.push_back(
            cat("pass '", name_, "' writes '", graph_.texture(texture).name,
                "' with usage 'sampled'; writes go through an attachment or storage"));
        return nullptr;
    }
    auto existing = std::find_if(accesses_.begin(), accesses_.end(),
                                 [&](const TextureAccess& a) { return a.texture == texture; });
    if (existing == accesses_.end()) {
        accesses_.push_back({texture, reads, writes, usage});
        return &accesses_.back();
    }
    existing->reads = existing->reads || reads;
    if (!writes) return &*existing;
    if (existing->writes && existing->usage != usage) {
        declarationErrors_.push_back(cat("pass '", name_, "' writes '", graph_.texture(texture).name,
                                         "' both as ", toString(existing->usage), " and as ",
                                         toString(usage)));
        return &*existing;
    }
    existing->writes = true;
    existing->usage = usage;
    return &*existing;
}

std::vector<TextureHandle> Pass::colorAttachments() const {
    std::vector<TextureHandle> out;
    for (const auto& a : accesses_) {
        if (a.writes && a.usage == TextureUsage::ColorAttachment) out.push_back(a.texture);
    }
    return out;
}

std::optional<TextureHandle> Pass::depthAttachment() const {
    for (const auto& a : accesses_) {
        if (a.writes && a.usage == TextureUsage::DepthAttachment) return a.texture;
    }
    return std::nullopt;
}

std::vector<TextureHandle> Pass::storageWrites() const {
    std::vector<TextureHandle> out;
    for (const auto& a : accesses_) {
        if (a.writes && a.usage == TextureUsage::Storage) out.push_back(a.texture);
    }
    return out;
}

std::vector<TextureHandle> Pass::sampledReads() const {
    std::vector<TextureHandle> out;
    for (const auto& a : accesses_) {
        if (a.onlyReads()) out.push_back(a.texture);
    }
    return out;
}

bool Pass::writesPresentedOutput() const {
    TextureHandle output = graph_.output();
    return std::any_of(accesses_.begin(), accesses_.end(),
                       [&](const TextureAccess& a) { return a.writes && a.texture == output; });
}

}  // namespace fx
