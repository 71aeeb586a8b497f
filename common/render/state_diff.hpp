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

// What a pass's draws write, which decides the state they depend on.
struct PassWrites {
    bool depth = false;  // a depth attachment (or the window's depth buffer)
    bool color = false;  // a colour attachment or the window
};

// The state a pass depends on but leaves to whoever ran before it, with the value it inherited:
// "depth test: off (inherited)". A pass writing depth depends on the depth test (and, while testing,
// on depth writes and the depth function; when it clears depth, on depth writes too, since the clear
// obeys the depth mask); a pass writing colour depends on blending (and, while
// blending, on the blend function) and the colour mask; any drawing pass depends on face culling.
// Empty when the pass declares all of it, which is the chapter's rule: each pass sets the state it
// depends on (the Shader effects chapter, §3.3).
std::vector<std::string> inheritedDependencies(const PassState& declared, const GlStateSnapshot& inherited,
                                               PassWrites writes);

}  // namespace fx
