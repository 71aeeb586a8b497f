#pragma once
// What one pass left behind, in words: the GL layer snapshots the state after a pass (glGet into a
// GlStateSnapshot) and this lists where it differs from a reference state, for the overlay and the
// report ("depth test: off (default on)").
#include <string>
#include <vector>

#include "render/pass_state.hpp"

namespace fx {

struct StateDifference {
    std::string field;         // "depth test"
    std::string value;         // "off"
    std::string defaultValue;  // "on"
    std::string text() const;  // "depth test: off (default on)"
};

// Differences in a fixed field order (viewport, depth, blend, culling, colour mask, clear values).
std::vector<StateDifference> diffState(const GlStateSnapshot& actual, const GlStateSnapshot& defaults);

}  // namespace fx
