#pragma once
// Applying a pass's declared state to GL, and reading back the state GL is really in, so the
// executor can report what each pass left behind for the next one.
#include "gl/gl.hpp"
#include "render/pass_state.hpp"

namespace fx {

// Sets every field the pass declared; unset fields stay as they are (on purpose, see PassState).
// The viewport is always set: the declared one, or the whole target.
void applyGlState(const PassState& state, Size2D targetSize);

// glGet of every field of GlStateSnapshot.
GlStateSnapshot snapshotGlState();

// Puts GL back into the snapshot's state (used to start each frame from the same state).
void restoreGlState(const GlStateSnapshot& snapshot);

}  // namespace fx
