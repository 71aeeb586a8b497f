#pragma once
// How many GL objects the current context holds, kind by kind: what a soak samples to see that nothing
// leaks (docs/reliability.md, "Soak"). Counted by asking glIs* of every name up to the next name the
// driver would give (an object made and deleted at once gives it), so objects fxlab never wrapped (Dear
// ImGui's, a driver's) count too.
#include <string>

namespace fx::gl {

struct LiveObjects {
    int textures = 0, buffers = 0, framebuffers = 0, renderbuffers = 0, vertexArrays = 0;
    int samplers = 0, queries = 0, programs = 0, shaders = 0, transformFeedbacks = 0;

    int total() const;
    bool operator==(const LiveObjects&) const = default;
};

// Needs a current context. Raises no GL error.
LiveObjects countLiveObjects();

// "textures,buffers,..." and the matching values, for a CSV.
std::string liveObjectsCsvHeader();
std::string liveObjectsCsvRow(const LiveObjects& objects);

}  // namespace fx::gl
