#include "app/lesson.hpp"

#include "base/log.hpp"

namespace fx {

Lesson*& Lesson::underConstruction() {
    thread_local Lesson* lesson = nullptr;
    return lesson;
}

Lesson::Lesson() {
    underConstruction() = this;
}

Lesson::~Lesson() {
    if (underConstruction() == this) underConstruction() = nullptr;
}

void Lesson::buildGpuMembers(const Scene& scene) {
    if (underConstruction() == this) underConstruction() = nullptr;  // made: nothing more joins it
    if (gpuMembersBuilt_) return;
    gpuMembersBuilt_ = true;
    for (const auto& build : gpuMembers_) build(scene);
}

void gpuMemberMisuse(const char* what) {
    log::error("fxlab: ", what, " (app/lesson.hpp: Gpu<T> is a lesson member, built before init())");
    std::abort();
}

}  // namespace fx
