#pragma once
// The pixel probe: the exact value a texture stores at one texel, read back from the texture
// itself (never from the displayed picture, which the range, exposure and channel toggles change),
// and the same place in the other members of its chain.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "gl/readback.hpp"
#include "ui/texture_chain.hpp"
#include "ui/texture_source.hpp"

namespace fx {

struct ProbeSample {
    std::string label;  // "mip 2", "bloom.down[3]"
    int level = 0;
    int x = 0, y = 0;  // texel coordinates, y from the bottom row (GL's order)
    Size2D size{};     // of the level
    int channels = 0;  // 0 when nothing could be read (the texture is not alive)
    gl::Texel texel;
};

// Reads texel (x, y) of a level; channels stays 0 outside the level or when the texture is not alive.
ProbeSample probeTexel(const TextureSource& source, int level, int x, int y);

// Looks a chain member up by name in the frame; the function the inspector passes resolves names
// to what is alive now.
using SourceLookup = std::function<TextureSource(const std::string& name)>;

// The texel that covers the same place in every member of a chain.
std::vector<ProbeSample> probeChain(const TextureChain& chain, const SourceLookup& lookup, int x, int y,
                                    Size2D from);

// A stored value as text: floats in the fewest digits that read back as the same float ("0.1",
// "65504", "1e-40", "nan", "-inf"); 8-bit UNORM values also as n/255.
std::string storedValueText(float value, TextureFormat format);

// The shortest decimal form that parses back to exactly `value`.
std::string exactFloatText(float value);

class PixelProbe {
public:
    // Where the probe looks: a texel of a level, of the viewed texture or of a member of its chain.
    struct Target {
        int level = 0, x = 0, y = 0;
        std::string texture;  // empty: the texture in the large view
    };

    // A pinned probe stays where it was put while the mouse moves on (right click in the view).
    void pin(Target target) { pinned_ = std::move(target); }
    void unpin() { pinned_.reset(); }
    bool pinned() const { return pinned_.has_value(); }
    // Where the probe is this frame: the pinned texel, else the hovered one, else nothing.
    std::optional<Target> target(const std::optional<Target>& hovered) const {
        return pinned_ ? pinned_ : hovered;
    }

    // Shows the probe's result: coordinates, one value per channel, and (for depth) the distance.
    static void draw(const ProbeSample& sample, const TextureSource& source, bool linearDepth,
                     float cameraNear, float cameraFar, bool pinned);

private:
    std::optional<Target> pinned_;
};

}  // namespace fx
