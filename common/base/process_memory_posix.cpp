#include "base/process_memory.hpp"

#include <cstdio>

#include <malloc.h>
#include <unistd.h>

namespace fx {

ProcessMemory processMemory() {
    ProcessMemory m;
    if (std::FILE* statm = std::fopen("/proc/self/statm", "r")) {
        unsigned long long size = 0, resident = 0;
        if (std::fscanf(statm, "%llu %llu", &size, &resident) == 2)
            m.residentBytes = resident * std::uint64_t(::sysconf(_SC_PAGESIZE));
        std::fclose(statm);
    }
    const struct mallinfo2 info = ::mallinfo2();
    m.heapBytes = std::uint64_t(info.uordblks) + std::uint64_t(info.hblkhd);
    return m;
}

}  // namespace fx
