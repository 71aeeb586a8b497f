#pragma once
// KHR_debug: every message the driver sends is logged, errors are counted, and tests can make any
// error fatal. Every GL error is a bug, except inside a scope a lesson opens on purpose to show one
// (lesson 02 reproduces the chapter's error flood); those are counted separately as "expected".
#include <cstdint>
#include <string>
#include <string_view>

#include "gl/gl.hpp"

namespace fx::gl {

struct DebugCounters {
    std::int64_t errors = 0;          // GL errors nobody asked for: each one is a bug
    std::int64_t expectedErrors = 0;  // errors inside an ExpectedErrorScope
    std::int64_t warnings = 0;        // performance, undefined and deprecated behaviour
    std::string lastError;            // the text of the latest unexpected error
};

// Installs the callback on the current context (synchronous, so a breakpoint lands on the call).
// Returns false when the context exposes no debug output; errors are then found by glGetError in
// drainErrorFlags().
bool installDebugOutput();

const DebugCounters& debugCounters();
void resetDebugCounters();

// Reads glGetError until it is clear and counts what it finds that the callback did not report.
// The runner calls it once a frame.
void drainErrorFlags();

// While one of these lives, GL errors count as expected instead of as bugs.
class ExpectedErrorScope {
public:
    explicit ExpectedErrorScope(std::string_view why);
    ~ExpectedErrorScope();
    ExpectedErrorScope(const ExpectedErrorScope&) = delete;
    ExpectedErrorScope& operator=(const ExpectedErrorScope&) = delete;
};

// A named group in debuggers (RenderDoc, apitrace) and in KHR_debug messages.
class DebugGroup {
public:
    explicit DebugGroup(std::string_view name);
    ~DebugGroup();
    DebugGroup(const DebugGroup&) = delete;
    DebugGroup& operator=(const DebugGroup&) = delete;
};

std::string_view errorName(GLenum error);

}  // namespace fx::gl
