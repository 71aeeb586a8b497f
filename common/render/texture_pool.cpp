#include "render/texture_pool.hpp"

#include <algorithm>

#include "base/log.hpp"

namespace fx {

TexturePool::TexturePool(TextureAllocator& allocator, int framesBeforeEviction)
    : allocator_(allocator), framesBeforeEviction_(std::max(framesBeforeEviction, 0)) {}

TexturePool::~TexturePool() {
    for (auto& entry : entries_) allocator_.destroy(entry.texture);
}

namespace {

bool holds(const std::vector<std::string>& names, std::string_view name) {
    return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

std::string TexturePool::labelFor(const std::vector<std::string>& names) {
    std::string label;
    for (const std::string& name : names) label += (label.empty() ? "" : std::string(kNameSeparator)) + name;
    return label;
}

void TexturePool::holdName(Entry& entry, std::string_view name) {
    if (!holds(entry.frameNames, name)) entry.frameNames.emplace_back(name);
    if (holds(entry.labelNames, name)) return;
    entry.labelNames.emplace_back(name);
    allocator_.relabel(entry.texture, labelFor(entry.labelNames));
}

NativeTexture TexturePool::acquire(const TextureSpec& spec, std::string_view label) {
    auto free = [&](const Entry& e) { return !e.inUse && e.spec == spec; };
    auto match = std::find_if(entries_.begin(), entries_.end(),
                              [&](const Entry& e) { return free(e) && holds(e.labelNames, label); });
    if (match == entries_.end()) match = std::find_if(entries_.begin(), entries_.end(), free);

    if (match != entries_.end()) {
        holdName(*match, label);
        match->inUse = true;
        match->lastUsedFrame = frame_;
        return match->texture;
    }

    NativeTexture texture = allocator_.create(spec, label);
    if (texture == 0) {
        log::error("texture pool: could not create '", label, "' (", toString(spec), ")");
        return 0;
    }
    entries_.push_back(
        {spec, texture, {std::string(label)}, {std::string(label)}, textureBytes(spec), frame_, true});
    peakBytes_ = std::max(peakBytes_, liveBytes());
    return texture;
}

void TexturePool::release(NativeTexture texture) {
    auto entry = std::find_if(entries_.begin(), entries_.end(),
                              [&](const Entry& e) { return e.texture == texture && e.inUse; });
    if (entry == entries_.end()) {
        log::warning("texture pool: texture ", texture, " released but not in use");
        return;
    }
    entry->inUse = false;
    entry->lastUsedFrame = frame_;
}

void TexturePool::endFrame() {
    for (std::size_t i = entries_.size(); i-- > 0;) {
        const Entry& e = entries_[i];
        if (!e.inUse && frame_ - e.lastUsedFrame >= static_cast<std::uint64_t>(framesBeforeEviction_)) {
            destroyEntry(i);
        }
    }
    for (auto& e : entries_) {
        // Textures still held across the frame boundary count as used in it.
        if (e.inUse) e.lastUsedFrame = frame_;
        // The label says what the texture held this frame (a name it no longer holds goes), so the next
        // frame, when it is like this one, relabels nothing. One unused this frame keeps its label.
        if (!e.frameNames.empty() && e.frameNames != e.labelNames) {
            e.labelNames = e.frameNames;
            allocator_.relabel(e.texture, labelFor(e.labelNames));
        }
        e.frameNames.clear();
        // One held across the boundary still holds its names next frame.
        if (e.inUse) e.frameNames = e.labelNames;
    }
    ++frame_;
}

void TexturePool::trim() {
    for (std::size_t i = entries_.size(); i-- > 0;) {
        if (!entries_[i].inUse) destroyEntry(i);
    }
}

void TexturePool::destroyEntry(std::size_t index) {
    allocator_.destroy(entries_[index].texture);
    entries_.erase(entries_.begin() + static_cast<std::ptrdiff_t>(index));
}

PoolStats TexturePool::stats() const {
    PoolStats s;
    s.peakBytes = peakBytes_;
    for (const auto& e : entries_) {
        s.liveBytes += e.bytes;
        ++s.liveTextures;
        if (e.inUse) {
            s.inUseBytes += e.bytes;
            ++s.inUseTextures;
        }
    }
    return s;
}

void TexturePool::resetPeak() {
    peakBytes_ = liveBytes();
}

}  // namespace fx
