#include "app/renderdoc_session.hpp"

#include <system_error>

#include "base/log.hpp"

namespace fx {

namespace fs = std::filesystem;

namespace {

// The file may be replaced only when it is a regular file or absent (the rule of base/file_io.hpp).
Status checkTarget(const fs::path& file) {
    std::error_code ec;
    const fs::file_status status = fs::symlink_status(file, ec);
    if (ec && ec != std::errc::no_such_file_or_directory)
        return Error{cat(file.string(), ": cannot be looked at (", ec.message(), ")")};
    if (fs::exists(status) && !fs::is_regular_file(status))
        return Error{cat(file.string(),
                         ": is not a regular file (a link, a folder or a device); the capture ",
                         "would replace it: choose another name")};
    return Status::success();
}

}  // namespace

Result<std::unique_ptr<RenderDocSession>> RenderDocSession::open(const RunOptions& options, int frames) {
    if (Status target = checkTarget(options.renderdoc); !target)
        return Error{cat("--renderdoc: ", target.error())};
    auto api = RenderDocApi::load();
    if (!api) return Error{api.error()};
    return std::unique_ptr<RenderDocSession>(new RenderDocSession(std::move(*api), options, frames));
}

RenderDocSession::RenderDocSession(std::unique_ptr<RenderDocApi> api, const RunOptions& options, int frames)
    : api_(std::move(api)), file_(options.renderdoc), open_(options.renderdocOpen) {
    if (options.renderdocFrame) frame_ = std::uint64_t(*options.renderdocFrame - 1);
    lastWanted_ = !frame_ && frames != 0;
    api_->quiet();
    const fs::path folder = file_.parent_path().empty() ? fs::path(".") : file_.parent_path();
    scratch_ = folder / cat(".", file_.filename().string(), ".renderdoc");
    api_->setCaptureTemplate(scratch_ / "capture");
    log::info("RenderDoc loaded (its in-application API ", api_->version(), "): ",
              frame_ ? cat("frame ", *frame_ + 1) : std::string(frames != 0 ? "the last frame" : "no frame"),
              " of the run will be captured into ", file_.string(),
              frames == 0 ? "; F9 captures the next frame" : "");
}

RenderDocSession::~RenderDocSession() {
    std::error_code ec;
    fs::remove_all(scratch_, ec);
}

fs::path RenderDocSession::capturePath(const fs::path& file, int n) {
    if (n <= 1) return file;
    return file.parent_path() / cat(file.stem().string(), "-", n, file.extension().string());
}

void RenderDocSession::frameStarts(std::uint64_t index, bool lastFrame) {
    if (capturing_) return;  // a frame that drew nothing (minimised): the capture goes on to the next
    bool wanted = std::exchange(asked_, false);
    if (frame_ && *frame_ == index) {
        frame_.reset();
        wanted = true;
    }
    if (lastWanted_ && lastFrame) {
        lastWanted_ = false;
        wanted = true;
    }
    if (!wanted) return;
    api_->startFrame();
    capturing_ = true;
}

std::optional<std::string> RenderDocSession::frameEnded() {
    if (!capturing_) return std::nullopt;
    capturing_ = false;
    auto written = api_->endFrame();
    if (!written) {
        failure_ = written.error();
        return failure_;
    }
    const fs::path target = capturePath(file_, written_ + 1);
    std::error_code ec;
    Status checked = checkTarget(target);
    if (checked) {
        if (!target.parent_path().empty()) fs::create_directories(target.parent_path(), ec);
        if (!ec) fs::rename(*written, target, ec);
    }
    if (!checked || ec) {
        failure_ =
            cat("--renderdoc: the capture could not be put at ", target.string(), " (",
                checked ? ec.message() : checked.error(), "); RenderDoc's file is ", written->string());
        return failure_;
    }
    ++written_;
    std::string said = cat("RenderDoc capture written: ", target.string());
    if (open_) {
        auto started = api_->openInReplayUi(target);
        said += started ? cat(" (qrenderdoc opens it, process ", *started, ")") : cat("; ", started.error());
    } else {
        said += cat(" (open it with: ", replayUiCommand(target), ")");
    }
    return said;
}

Status RenderDocSession::finish() {
    if (capturing_) (void)api_->endFrame();
    capturing_ = false;
    if (!failure_.empty()) return Error{failure_};
    if (frame_)
        return Error{
            cat("--renderdoc-frame: the run ended before frame ", *frame_ + 1, "; nothing captured")};
    if (lastWanted_)
        return Error{"--renderdoc: the run ended before its last frame was drawn; nothing captured"};
    return Status::success();
}

}  // namespace fx
