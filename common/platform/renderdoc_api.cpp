#include "platform/renderdoc_api.hpp"

#include "base/log.hpp"

#include <cstdlib>

#include "gl/debug_output.hpp"
#include "gl/gl.hpp"

#if !defined(_WIN32)
#include <dlfcn.h>
#endif
#if __has_include(<renderdoc_app.h>)
#include <renderdoc_app.h>
#define FX_HAVE_RENDERDOC_APP 1
#endif

namespace fx {

namespace fs = std::filesystem;

namespace {

[[maybe_unused]] constexpr const char* kLibrary = "librenderdoc.so";
[[maybe_unused]] constexpr const char* kPackages =
    "Debian packages renderdoc (librenderdoc, qrenderdoc) and librenderdoc-dev";
// Set for the second start, so that a library that is preloaded and still not found stops there.
[[maybe_unused]] constexpr const char* kPreloadMark = "FXLAB_RENDERDOC_PRELOADED";

[[maybe_unused]] std::string missingLibrary(const char* why) {
    return cat("--renderdoc: ", kLibrary, " could not be loaded (", why ? why : "not found",
               "); install RenderDoc: apt-get install renderdoc (", kPackages, ")");
}

// The library in the process, or why not.
[[maybe_unused]] Result<void*> openLibrary() {
#if defined(_WIN32)
    return Error{"--renderdoc: RenderDoc's in-application API is loaded on Linux only in this build"};
#else
    if (void* loaded = dlopen(kLibrary, RTLD_NOW | RTLD_NOLOAD)) return loaded;
    return Error{cat("--renderdoc: ", kLibrary, " is not in the process although it was preloaded (",
                     kPreloadMark, " is set): RenderDoc cannot hook GL here")};
#endif
}

}  // namespace

Result<bool> prepareRenderDocStart() {
#if defined(_WIN32)
    return Error{"--renderdoc: RenderDoc's in-application API is loaded on Linux only in this build"};
#else
    if (dlopen(kLibrary, RTLD_NOW | RTLD_NOLOAD)) {
        // This is the start with the library preloaded: what runs from here (another lesson, a step's
        // run) does not inherit it unless it asks for RenderDoc itself.
        if (std::getenv(kPreloadMark)) {
            std::string preload = std::getenv("LD_PRELOAD") ? std::getenv("LD_PRELOAD") : "";
            const std::string ours = cat(kLibrary, " ");
            if (preload.rfind(ours, 0) == 0) preload.erase(0, ours.size());
            if (preload.empty() || preload == kLibrary)
                unsetenv("LD_PRELOAD");
            else
                setenv("LD_PRELOAD", preload.c_str(), 1);
            unsetenv(kPreloadMark);
        }
        return false;
    }
    if (std::getenv(kPreloadMark))
        return Error{cat("--renderdoc: ", kLibrary, " was preloaded but is not in the process")};
    // Loadable at all? (Loaded this late it hooks nothing; the new start preloads it.)
    if (!dlopen(kLibrary, RTLD_NOW | RTLD_LOCAL)) return Error{missingLibrary(dlerror())};
    const char* before = std::getenv("LD_PRELOAD");
    const std::string preload = before && *before ? cat(kLibrary, " ", before) : std::string(kLibrary);
    setenv("LD_PRELOAD", preload.c_str(), 1);
    setenv(kPreloadMark, "1", 1);
    return true;
#endif
}

namespace {

[[maybe_unused]] void* findSymbol(void* library, const char* name) {
#if defined(_WIN32)
    (void)library;
    (void)name;
    return nullptr;
#else
    return dlsym(library, name);
#endif
}

}  // namespace

#if defined(FX_HAVE_RENDERDOC_APP)

struct RenderDocApi::Functions : RENDERDOC_API_1_4_1 {};

Result<std::unique_ptr<RenderDocApi>> RenderDocApi::load() {
    auto library = openLibrary();
    if (!library) return Error{library.error()};
    auto getApi = reinterpret_cast<pRENDERDOC_GetAPI>(findSymbol(*library, "RENDERDOC_GetAPI"));
    if (!getApi)
        return Error{cat("--renderdoc: ", kLibrary, " has no RENDERDOC_GetAPI (not RenderDoc's library?)")};
    void* api = nullptr;
    if (getApi(eRENDERDOC_API_Version_1_4_1, &api) != 1 || !api) {
        return Error{
            cat("--renderdoc: ", kLibrary,
                " does not offer RenderDoc's in-application API 1.4.1 (RenderDoc 1.8 or later is needed)")};
    }
    return std::unique_ptr<RenderDocApi>(new RenderDocApi(static_cast<Functions*>(api)));
}

RenderDocApi::RenderDocApi(Functions* api) : api_(api) {
    int major = 0, minor = 0, patch = 0;
    api_->GetAPIVersion(&major, &minor, &patch);
    version_ = cat(major, ".", minor, ".", patch);
}

RenderDocApi::~RenderDocApi() = default;

void RenderDocApi::quiet() {
    api_->SetCaptureKeys(nullptr, 0);
    api_->SetFocusToggleKeys(nullptr, 0);
    api_->MaskOverlayBits(eRENDERDOC_Overlay_None, eRENDERDOC_Overlay_None);
}

void RenderDocApi::setCaptureTemplate(const fs::path& pathTemplate) {
    api_->SetCaptureFilePathTemplate(pathTemplate.string().c_str());
}

void RenderDocApi::startFrame() {
    api_->StartFrameCapture(nullptr, nullptr);
}

bool RenderDocApi::capturing() const {
    return api_->IsFrameCapturing() != 0;
}

Result<fs::path> RenderDocApi::endFrame() {
    const std::uint32_t before = api_->GetNumCaptures();
    gl::drainErrorFlags();  // the frame's own errors are counted as fxlab's first
    const bool ended = api_->EndFrameCapture(nullptr, nullptr) == 1;
    // RenderDoc reads the default framebuffer for the capture's thumbnail, which a surfaceless
    // context lacks (GL_INVALID_FRAMEBUFFER_OPERATION): RenderDoc's error, not the lesson's.
    while (glGetError() != GL_NO_ERROR) {
    }
    if (!ended)
        return Error{
            "RenderDoc could not capture the frame (its log says why: ~/.local/share/renderdoc or /tmp/RenderDoc)"};
    const std::uint32_t count = api_->GetNumCaptures();
    if (count <= before) return Error{"RenderDoc captured the frame but lists no new capture file"};
    std::uint32_t length = 0;
    if (!api_->GetCapture(count - 1, nullptr, &length, nullptr) || length == 0)
        return Error{"RenderDoc did not say where it wrote the capture"};
    std::string file(length, '\0');
    api_->GetCapture(count - 1, file.data(), &length, nullptr);
    file.resize(file.find('\0') == std::string::npos ? file.size() : file.find('\0'));
    return fs::path(file);
}

Result<unsigned> RenderDocApi::openInReplayUi(const fs::path& capture) {
    const std::string line = cat("\"", capture.string(), "\"");
    const std::uint32_t pid = api_->LaunchReplayUI(0, line.c_str());
    if (pid == 0) return Error{cat("RenderDoc could not start qrenderdoc; run: ", replayUiCommand(capture))};
    return unsigned(pid);
}

#else  // built without renderdoc_app.h

struct RenderDocApi::Functions {};

Result<std::unique_ptr<RenderDocApi>> RenderDocApi::load() {
    return Error{cat("--renderdoc: fxlab was built without RenderDoc's header renderdoc_app.h; install ",
                     kPackages, " and build again (./fxlab setup)")};
}
RenderDocApi::RenderDocApi(Functions* api) : api_(api) {}
RenderDocApi::~RenderDocApi() = default;
void RenderDocApi::quiet() {}
void RenderDocApi::setCaptureTemplate(const fs::path&) {}
void RenderDocApi::startFrame() {}
bool RenderDocApi::capturing() const {
    (void)api_;  // nothing to ask: built without the API's header
    return false;
}
Result<fs::path> RenderDocApi::endFrame() {
    return Error{"RenderDoc is not loaded"};
}
Result<unsigned> RenderDocApi::openInReplayUi(const fs::path& capture) {
    return Error{cat("RenderDoc is not loaded; run: ", replayUiCommand(capture))};
}

#endif

std::string replayUiCommand(const fs::path& capture) {
    std::string quoted = "'";
    for (char ch : capture.string()) quoted += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
    return cat("qrenderdoc ", quoted, "'");
}

}  // namespace fx
