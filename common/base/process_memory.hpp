#pragma once
// What this process holds in memory now: what a soak samples to see that nothing grows
// (docs/reliability.md, "Soak").
#include <cstdint>

namespace fx {

struct ProcessMemory {
    std::uint64_t residentBytes = 0;  // pages in RAM (/proc/self/statm), the driver's included
    std::uint64_t heapBytes = 0;      // bytes malloc has handed out and not had back (mallinfo2)
};

ProcessMemory processMemory();

}  // namespace fx
