#pragma once
// --renderdoc FILE.rdc: which frames of a run RenderDoc captures and where the captures go.
//
// The run's last frame (or --renderdoc-frame N) is captured, window or headless, and in a window F9
// captures the next frame too. Each capture is bracketed by RenderDoc's StartFrameCapture and
// EndFrameCapture around the frame's whole work (the frame loop's two hooks), so a headless frame,
// which is never presented, is captured like a window's. RenderDoc writes into a folder of its own
// beside FILE; the finished capture is then renamed into place under the rule every written file
// follows (a link, a folder or a device at FILE is refused, never replaced).
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "app/run_options.hpp"
#include "base/result.hpp"
#include "platform/renderdoc_api.hpp"

namespace fx {

class RenderDocSession {
public:
    // Loads RenderDoc; must come before the GL context is made. An error names what to install.
    static Result<std::unique_ptr<RenderDocSession>> open(const RunOptions& options, int frames);
    ~RenderDocSession();
    RenderDocSession(const RenderDocSession&) = delete;
    RenderDocSession& operator=(const RenderDocSession&) = delete;

    // F9: the next frame is captured (into FILE-2.rdc, FILE-3.rdc ... once FILE has one).
    void captureNextFrame() { asked_ = true; }
    // At a frame's start (index 0-based): starts the capture when this frame is wanted.
    void frameStarts(std::uint64_t index, bool lastFrame);
    // After the frame is presented: ends its capture and moves the file into place; what to tell the
    // user ("RenderDoc capture: out/06.rdc"), or nothing when no capture ended.
    std::optional<std::string> frameEnded();
    // When the run ends: an error when the frame asked for was never captured (or a capture failed).
    Status finish();

    // Where the n-th capture of this run goes (1: FILE itself; then FILE-2.rdc ...), not taken yet.
    static std::filesystem::path capturePath(const std::filesystem::path& file, int n);

private:
    RenderDocSession(std::unique_ptr<RenderDocApi> api, const RunOptions& options, int frames);

    std::unique_ptr<RenderDocApi> api_;
    std::filesystem::path file_;
    std::filesystem::path scratch_;       // RenderDoc's own folder beside file_, removed when the run ends
    std::optional<std::uint64_t> frame_;  // the frame asked for (0-based); nothing: the last
    bool lastWanted_ = true;              // headless or --frames: the run's last frame is captured
    bool open_ = false;                   // --renderdoc-open
    bool asked_ = false;                  // F9
    bool capturing_ = false;
    int written_ = 0;
    std::string failure_;
};

}  // namespace fx
