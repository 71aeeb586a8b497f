#include "ui/texture_chain.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "base/log.hpp"

namespace fx {

std::optional<IndexedName> parseIndexedName(std::string_view name) {
    if (name.size() < 4 || name.back() != ']') return std::nullopt;
    auto open = name.rfind('[');
    if (open == std::string_view::npos || open == 0 || open + 2 > name.size() - 1) return std::nullopt;
    std::string_view digits = name.substr(open + 1, name.size() - open - 2);
    int index = 0;
    auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), index);
    if (ec != std::errc() || end != digits.data() + digits.size() || index < 0) return std::nullopt;
    return IndexedName{std::string(name.substr(0, open)), index};
}

TextureChain mipChain(std::string_view name, const TextureSpec& spec) {
    TextureChain chain;
    if (spec.mipLevels <= 1) return chain;
    chain.kind = TextureChain::Kind::MipLevels;
    chain.title = cat(name, ": ", spec.mipLevels, " mip levels");
    for (int level = 0; level < spec.mipLevels; ++level) {
        Size2D size{mipLevelSize(spec.width, level), mipLevelSize(spec.height, level)};
        chain.members.push_back({std::string(name), level, size, cat("mip ", level)});
    }
    return chain;
}

TextureChain findChain(const FrameReport& frame, std::string_view name) {
    if (auto indexed = parseIndexedName(name)) {
        std::vector<std::pair<int, const TextureRecord*>> found;
        for (const TextureRecord& t : frame.textures) {
            auto other = parseIndexedName(t.name);
            if (other && other->base == indexed->base) found.emplace_back(other->index, &t);
        }
        if (found.size() >= 2) {
            std::sort(found.begin(), found.end(), [](auto& a, auto& b) { return a.first < b.first; });
            TextureChain chain;
            chain.kind = TextureChain::Kind::Named;
            chain.title = cat(indexed->base, "[*]: ", found.size(), " textures");
            for (auto& [index, t] : found) {
                chain.members.push_back({t->name, 0, {t->spec.width, t->spec.height}, t->name});
            }
            return chain;
        }
    }
    if (const TextureRecord* t = frame.findTexture(name)) return mipChain(name, t->spec);
    return {};
}

int mapTexelCoordinate(int x, int from, int to) {
    if (from <= 0 || to <= 0) return 0;
    auto mapped = static_cast<int>(std::floor((double(x) + 0.5) * double(to) / double(from)));
    return std::clamp(mapped, 0, to - 1);
}

}  // namespace fx
