#pragma once
// Chains of textures the inspector shows side by side: the mip levels of one texture, or the
// textures of a named chain such as bloom.down[0], bloom.down[1], ... (written `bloom.down[*]`).
// Pure logic on the frame report, so the strip and the probe agree on what a chain is.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "render/frame_report.hpp"

namespace fx {

struct ChainMember {
    std::string texture;  // the texture's name
    int level = 0;        // the mip level this member shows
    Size2D size{};        // the size of that level
    std::string label;    // "mip 3" or "bloom.down[3]"
};

struct TextureChain {
    enum class Kind { None, MipLevels, Named };
    Kind kind = Kind::None;
    std::string title;  // "scene.color: 11 mip levels" or "bloom.down[*]: 6 textures"
    std::vector<ChainMember> members;
};

// "bloom.down[3]" -> {"bloom.down", 3}; nothing for a name without a trailing [index].
struct IndexedName {
    std::string base;
    int index = 0;
};
std::optional<IndexedName> parseIndexedName(std::string_view name);

// The mip levels of one texture: every level from 0 to mipLevels - 1 with GL's sizes.
TextureChain mipChain(std::string_view name, const TextureSpec& spec);

// The chain `name` belongs to in this frame: its named chain when the frame has at least two
// textures base[i] (ordered by index), else its mip levels when it has more than one, else none.
TextureChain findChain(const FrameReport& frame, std::string_view name);

// The texel of another member that covers the same place as texel (x, y) of a level `from` in size:
// floor((x + 0.5) * to / from), clamped to the member.
int mapTexelCoordinate(int x, int from, int to);

}  // namespace fx
