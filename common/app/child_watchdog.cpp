// The registry of work a child can do, and the child's side of the Windows way (child_watchdog.hpp).
#include "app/child_watchdog.hpp"

#include <map>
#include <mutex>

#include "base/file_io.hpp"
#include "base/log.hpp"

namespace fx {
namespace {

std::mutex& registryMutex() {
    static std::mutex m;
    return m;
}
std::map<std::string, ChildWork>& registry() {
    static std::map<std::string, ChildWork> works;
    return works;
}

}  // namespace

void registerChildWork(const std::string& name, ChildWork work) {
    std::lock_guard lock(registryMutex());
    registry()[name] = std::move(work);
}

const ChildWork* detail::findChildWork(const std::string& name) {
    std::lock_guard lock(registryMutex());
    auto it = registry().find(name);
    return it == registry().end() ? nullptr : &it->second;
}

std::optional<int> runChildWorkIfAsked(const std::vector<std::string>& arguments) {
    if (arguments.size() < 2 || arguments[0] != detail::kChildFlag) return std::nullopt;
    const ChildWork* work = detail::findChildWork(arguments[1]);
    if (!work) {
        log::error(detail::kChildFlag, ": no work named \"", arguments[1], "\"");
        return 2;
    }
    const std::string answer = (*work)(std::vector<std::string>(arguments.begin() + 2, arguments.end()));
    if (Status written = writeStandardOutput(answer); !written) {
        log::error(written.error());
        return 1;
    }
    return 0;
}

}  // namespace fx
