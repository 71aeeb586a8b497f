#include "gl/context_guard.hpp"

#include <atomic>

#include "base/log.hpp"

namespace fx::gl {
namespace {
thread_local bool alive = false;
std::atomic<std::int64_t> orphans{0};
}  // namespace

bool contextAlive() {
    return alive;
}
void setContextAlive(bool isAlive) {
    alive = isAlive;
}

std::int64_t orphanedNames() {
    return orphans.load();
}

void noteOrphanedName(const char* kind) {
    if (orphans.fetch_add(1) == 0) {
        log::warning("a GL ", kind,
                     " outlived its context and was not deleted (destroy GL objects before the context)");
    }
}

}  // namespace fx::gl
