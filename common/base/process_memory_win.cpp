// Process memory on Windows: the working set (what Windows calls resident) and the bytes the C
// runtime's heap has handed out, walked with _heapwalk (msvcrt has no mallinfo).
#include "base/process_memory.hpp"

#include <windows.h>
// windows.h first: psapi.h needs its types.
#include <malloc.h>
#include <psapi.h>

namespace fx {

ProcessMemory processMemory() {
    ProcessMemory m;
    PROCESS_MEMORY_COUNTERS counters{};
    counters.cb = sizeof counters;
    if (GetProcessMemoryInfo(GetCurrentProcess(), &counters, sizeof counters))
        m.residentBytes = std::uint64_t(counters.WorkingSetSize);
    _HEAPINFO entry{};
    entry._pentry = nullptr;
    std::uint64_t used = 0;
    while (_heapwalk(&entry) == _HEAPOK)
        if (entry._useflag == _USEDENTRY) used += entry._size;
    m.heapBytes = used;
    return m;
}

}  // namespace fx
