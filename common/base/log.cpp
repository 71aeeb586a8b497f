#include "base/log.hpp"

#include <cstdio>
#include <map>
#include <mutex>

namespace fx::log {
namespace {

struct Registry {
    std::mutex mutex;
    std::map<int, std::function<void(Level, std::string_view)>> sinks;
    int nextId = 1;
    Level consoleLevel = Level::info;
};

Registry& registry() {
    static Registry r;
    return r;
}

const char* prefix(Level level) {
    switch (level) {
        case Level::debug:
            return "debug: ";
        case Level::info:
            return "";
        case Level::warning:
            return "warning: ";
        case Level::error:
            return "error: ";
    }
    return "";
}

}  // namespace

void write(Level level, std::string_view message) {
    auto& r = registry();
    std::lock_guard lock(r.mutex);
    if (level >= r.consoleLevel) {
        std::fprintf(stderr, "%s%.*s\n", prefix(level), static_cast<int>(message.size()), message.data());
    }
    for (auto& [id, sink] : r.sinks) sink(level, message);
}

int addSink(std::function<void(Level, std::string_view)> sink) {
    auto& r = registry();
    std::lock_guard lock(r.mutex);
    int id = r.nextId++;
    r.sinks.emplace(id, std::move(sink));
    return id;
}

void removeSink(int id) {
    auto& r = registry();
    std::lock_guard lock(r.mutex);
    r.sinks.erase(id);
}

void setConsoleLevel(Level level) {
    auto& r = registry();
    std::lock_guard lock(r.mutex);
    r.consoleLevel = level;
}

}  // namespace fx::log
