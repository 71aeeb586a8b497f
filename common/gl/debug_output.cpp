#include "gl/debug_output.hpp"

#include "base/log.hpp"

namespace fx::gl {
namespace {

DebugCounters counters;
int expectedScopes = 0;
bool callbackInstalled = false;
std::int64_t errorsSeenByCallbackThisDrain = 0;

const char* sourceName(GLenum source) {
    switch (source) {
        case GL_DEBUG_SOURCE_API:
            return "api";
        case GL_DEBUG_SOURCE_WINDOW_SYSTEM:
            return "window system";
        case GL_DEBUG_SOURCE_SHADER_COMPILER:
            return "shader compiler";
        case GL_DEBUG_SOURCE_THIRD_PARTY:
            return "third party";
        case GL_DEBUG_SOURCE_APPLICATION:
            return "application";
        default:
            return "other";
    }
}

void countError(std::string_view text) {
    if (expectedScopes > 0) {
        ++counters.expectedErrors;
        return;
    }
    ++counters.errors;
    counters.lastError = std::string(text);
    log::error("GL: ", text);
}

void GLAPIENTRY onDebugMessage(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length,
                               const GLchar* message, const void*) {
    std::string_view text(
        message, length < 0 ? std::char_traits<char>::length(message) : static_cast<std::size_t>(length));
    switch (type) {
        case GL_DEBUG_TYPE_ERROR:
            // A failed compile is not a GL error: the Program reports it with file and line.
            if (source == GL_DEBUG_SOURCE_SHADER_COMPILER) break;
            ++errorsSeenByCallbackThisDrain;
            countError(cat("[", sourceName(source), " #", id, "] ", text));
            break;
        case GL_DEBUG_TYPE_PUSH_GROUP:
        case GL_DEBUG_TYPE_POP_GROUP:
        case GL_DEBUG_TYPE_MARKER:
            break;
        case GL_DEBUG_TYPE_PERFORMANCE:
        case GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR:
        case GL_DEBUG_TYPE_DEPRECATED_BEHAVIOR:
        case GL_DEBUG_TYPE_PORTABILITY:
            if (severity == GL_DEBUG_SEVERITY_NOTIFICATION) break;
            ++counters.warnings;
            log::debug("GL (", sourceName(source), "): ", text);
            break;
        default:
            if (severity != GL_DEBUG_SEVERITY_NOTIFICATION) log::debug("GL: ", text);
            break;
    }
}

}  // namespace

bool installDebugOutput() {
    if (!GLAD_GL_KHR_debug && !GLAD_GL_VERSION_4_3) return false;
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(onDebugMessage, nullptr);
    glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
    callbackInstalled = glIsEnabled(GL_DEBUG_OUTPUT) == GL_TRUE;
    return callbackInstalled;
}

const DebugCounters& debugCounters() {
    return counters;
}

void resetDebugCounters() {
    counters = {};
    errorsSeenByCallbackThisDrain = 0;
}

void drainErrorFlags() {
    std::int64_t flags = 0;
    GLenum lastFlag = GL_NO_ERROR;
    for (GLenum e = glGetError(); e != GL_NO_ERROR; e = glGetError()) {
        ++flags;
        lastFlag = e;
        if (flags > 64) break;  // a lost context can report forever
    }
    // The callback reports each error once; glGetError keeps only one flag per kind, so it can only
    // add to the count when the callback saw nothing.
    if (flags > 0 && (!callbackInstalled || errorsSeenByCallbackThisDrain == 0)) {
        countError(cat("glGetError: ", errorName(lastFlag), " (not reported through debug output)"));
    }
    errorsSeenByCallbackThisDrain = 0;
}

ExpectedErrorScope::ExpectedErrorScope(std::string_view why) {
    ++expectedScopes;
    log::debug("GL errors are expected for now: ", why);
}

ExpectedErrorScope::~ExpectedErrorScope() {
    drainErrorFlags();
    --expectedScopes;
}

DebugGroup::DebugGroup(std::string_view name) {
    glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, static_cast<GLsizei>(name.size()), name.data());
}

DebugGroup::~DebugGroup() {
    glPopDebugGroup();
}

std::string_view errorName(GLenum error) {
    switch (error) {
        case GL_NO_ERROR:
            return "GL_NO_ERROR";
        case GL_INVALID_ENUM:
            return "GL_INVALID_ENUM";
        case GL_INVALID_VALUE:
            return "GL_INVALID_VALUE";
        case GL_INVALID_OPERATION:
            return "GL_INVALID_OPERATION";
        case GL_INVALID_FRAMEBUFFER_OPERATION:
            return "GL_INVALID_FRAMEBUFFER_OPERATION";
        case GL_OUT_OF_MEMORY:
            return "GL_OUT_OF_MEMORY";
        case GL_STACK_OVERFLOW:
            return "GL_STACK_OVERFLOW";
        case GL_STACK_UNDERFLOW:
            return "GL_STACK_UNDERFLOW";
        default:
            return "unknown GL error";
    }
}

}  // namespace fx::gl
