#pragma once
// The lesson's three simulation paths by name, and the particle counts its steps and its bench run:
// shared by the lesson's steps (fire_lesson.cpp) and its simulation paths (fire_simulation.cpp).
namespace lesson07 {

inline constexpr const char* kPathNames[] = {"objects", "instanced", "gpu"};
// The bench's workloads: every path at every count, in one sweep so their times share one run.
inline constexpr int kWorkloadCounts[] = {100, 1000, 10000, 100000};
inline constexpr int kInstancedCount = 2000;  // step 3's fire
inline constexpr int kGpuCount = 100000;      // step 4's fire
// The chapter's emitter moved aside by this much for step 2's two fires (m, along x).
inline constexpr float kSideBySide = 0.9f;

}  // namespace lesson07
