#pragma once
// Every level of a mip chain (or every texture of a named chain such as bloom.down[*]) side by
// side at once, each labelled with its size and marked where the probe is. Tiles halve in height
// from one member to the next, like the levels themselves, down to a size where a 1x1 level is still
// a visible square, so a whole chain fits in one row. RenderDoc shows one level at a time; a bloom
// chain is understood by seeing all of them together.
#include <optional>
#include <string>
#include <vector>

#include <imgui.h>

#include "ui/pixel_probe.hpp"
#include "ui/texture_chain.hpp"
#include "ui/texture_display.hpp"

namespace fx {

class ChainStrip {
public:
    struct Interaction {
        std::optional<std::size_t> clicked;  // a member was clicked: show it in the large view
        std::optional<std::size_t> hoveredMember;
        std::optional<PixelProbe::Target> hovered;  // texel of the hovered member
    };

    // `settings` are the selected texture's (each member uses them at its own level). `samples`, when
    // not empty, holds the probe's value in each member (probeChain's order). `current` is the
    // member the large view shows. The first tile is `firstHeight` pixels high.
    Interaction draw(const TextureDisplay& display, const TextureChain& chain, const SourceLookup& lookup,
                     const ViewSettings& settings, const std::vector<ProbeSample>& samples,
                     std::optional<std::size_t> current, float firstHeight);

    // The height of member i's tile: halving from firstHeight, never below a third of it.
    static int tileHeight(std::size_t member, float firstHeight);

    // The tiles drawn by the last draw(): what a test checks.
    struct Tile {
        std::string label;
        Size2D size{};                   // of the member's level
        int width = 0, height = 0;       // of the tile on screen
        bool drawn = false;              // the member was alive and rendered
        float screenX = 0, screenY = 0;  // the tile's top-left corner on the screen
    };
    const std::vector<Tile>& tiles() const { return tiles_; }

private:
    std::vector<DisplaySurface> surfaces_;
    std::vector<Tile> tiles_;
};

}  // namespace fx
