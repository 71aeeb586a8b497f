#include "app/resource_log.hpp"

#include "base/file_io.hpp"
#include "base/log.hpp"
#include "base/process_memory.hpp"
#include "gl/live_objects.hpp"

namespace fx {

void ResourceLog::atFrame(std::uint64_t index, int step, Size2D size) {
    if (!enabled() || index == 0 || index % kInterval != 0) return;
    if (csv_.empty())
        csv_ = cat("frame,step,width,height,residentKiB,heapKiB,", gl::liveObjectsCsvHeader(), "\n");
    const ProcessMemory memory = processMemory();
    csv_ += cat(index, ",", step + 1, ",", size.width, ",", size.height, ",", memory.residentBytes / 1024,
                ",", memory.heapBytes / 1024, ",", gl::liveObjectsCsvRow(gl::countLiveObjects()), "\n");
}

Status ResourceLog::write() const {
    if (!enabled()) return Status::success();
    return writeFileAtomically(file_, csv_);
}

}  // namespace fx
