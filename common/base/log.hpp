#pragma once
// One place that prints: lessons, loaders and the GL debug callback all log through here, so tests
// can capture what a run said and the overlay can show the latest lines.
#include <functional>
#include <sstream>
#include <string>
#include <string_view>

namespace fx {

// Joins any streamable values into one string: cat("level ", 3, " is ", 1.5f).
template <class... Args>
std::string cat(const Args&... args) {
    std::ostringstream out;
    (out << ... << args);
    return out.str();
}

namespace log {

enum class Level { debug, info, warning, error };

void write(Level level, std::string_view message);

// Tests and the overlay listen to everything that is logged; returns an id for removeSink.
int addSink(std::function<void(Level, std::string_view)> sink);
void removeSink(int id);

// Lines below this level are not printed to stderr (sinks still see them).
void setConsoleLevel(Level level);

template <class... Args>
void debug(const Args&... args) {
    write(Level::debug, cat(args...));
}
template <class... Args>
void info(const Args&... args) {
    write(Level::info, cat(args...));
}
template <class... Args>
void warning(const Args&... args) {
    write(Level::warning, cat(args...));
}
template <class... Args>
void error(const Args&... args) {
    write(Level::error, cat(args...));
}

}  // namespace log
}  // namespace fx
