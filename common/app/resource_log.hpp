#pragma once
// --resource-log FILE: every tenth frame, what the run holds (the process's memory and the context's
// live GL objects, kind by kind), written as CSV when the run ends. A soak (tools/soak/run_soak.sh,
// docs/reliability.md) reads it to show that nothing grows once every step and size has been seen.
#include <cstdint>
#include <filesystem>
#include <string>

#include "base/result.hpp"
#include "base/size2d.hpp"

namespace fx {

class ResourceLog {
public:
    static constexpr std::uint64_t kInterval = 10;  // frames between samples

    explicit ResourceLog(std::filesystem::path file) : file_(std::move(file)) {}
    bool enabled() const { return !file_.empty(); }
    // Called at the start of every frame: samples on frames 10, 20, ... (what the frames before left).
    void atFrame(std::uint64_t index, int step, Size2D size);
    Status write() const;

private:
    std::filesystem::path file_;
    std::string csv_;
};

}  // namespace fx
