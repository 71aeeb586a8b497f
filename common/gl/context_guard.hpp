#pragma once
// Whether a GL context is current on this thread. Every GL object owner checks it before deleting
// its name, so that nothing is deleted after its context is gone (the chapter's lifetime pitfall:
// program objects released after glfwTerminate). An owner that outlives its context is counted and
// reported instead of calling into a dead context.
#include <cstdint>

namespace fx::gl {

bool contextAlive();
void setContextAlive(bool alive);

// How many GL names were dropped because their context was already gone.
std::int64_t orphanedNames();
void noteOrphanedName(const char* kind);

}  // namespace fx::gl
