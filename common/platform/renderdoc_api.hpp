#pragma once
// RenderDoc's in-application API (renderdoc_app.h), loaded at run time: librenderdoc.so is opened
// with dlopen and asked for its API through RENDERDOC_GetAPI, so fxlab builds and runs without
// RenderDoc, and a run asks for it only with --renderdoc (app/renderdoc_session.hpp).
//
// RenderDoc hooks GL only when its library is in the process before any GL library is opened: on
// Linux, loaded late, it finds no GL to hook (EndFrameCapture fails), so a run with --renderdoc starts
// itself once more with librenderdoc.so preloaded (prepareRenderDocStart), and load() then finds it.
// A frame is captured between startFrame() and endFrame(), called around the frame's work, so a
// headless frame (which is never presented) is captured as well as a window's.
#include <filesystem>
#include <memory>
#include <string>

#include "base/result.hpp"

namespace fx {

// Whether the process must start again with RenderDoc's library preloaded: false when it is in the
// process already (this is that second start, or qrenderdoc or renderdoccmd started us); true when
// LD_PRELOAD is now set for a new start (the caller execs itself); an error naming the package when
// the library cannot be loaded at all.
Result<bool> prepareRenderDocStart();

class RenderDocApi {
public:
    // The library and its API, or why not, naming what to install: "librenderdoc.so not found
    // (Debian package librenderdoc) ...". Also refused when fxlab was built without renderdoc_app.h.
    static Result<std::unique_ptr<RenderDocApi>> load();
    ~RenderDocApi();
    RenderDocApi(const RenderDocApi&) = delete;
    RenderDocApi& operator=(const RenderDocApi&) = delete;

    // "1.24.0": the library's API version.
    const std::string& version() const { return version_; }

    // RenderDoc's own keys (F12, Print Screen) and its text over the picture are off: F12 is fxlab's
    // screenshot, and the text would cover the lesson's title. The run's key captures instead.
    void quiet();
    // RenderDoc writes captures at this path with "_frameN.rdc" added; a folder it creates if needed.
    void setCaptureTemplate(const std::filesystem::path& pathTemplate);
    // Everything from here to endFrame() is one frame of the capture (any context, any window).
    void startFrame();
    bool capturing() const;
    // Ends the frame's capture; the file RenderDoc wrote, or why it wrote none.
    Result<std::filesystem::path> endFrame();
    // Starts qrenderdoc on the capture; its process id, or why not.
    Result<unsigned> openInReplayUi(const std::filesystem::path& capture);

private:
    struct Functions;
    explicit RenderDocApi(Functions* api);
    Functions* api_ = nullptr;
    std::string version_;
};

// The line to run to open a capture by hand: "qrenderdoc 'out/06.rdc'".
std::string replayUiCommand(const std::filesystem::path& capture);

}  // namespace fx
