#include "render_gl/pass_timer.hpp"

#include "base/log.hpp"
#include "gl/debug_output.hpp"

namespace fx {

namespace {

// The fenced timing's waits stand in a group of their own, so that a debugger's event list does not
// show them as the lesson's own glFinish calls.
void timingFence(std::string_view when) {
    gl::DebugGroup group(when);
    glFinish();
}

}  // namespace

std::string_view toString(TimingMethod method) {
    switch (method) {
        case TimingMethod::GpuTimestamps:
            return "GL_TIMESTAMP queries";
        case TimingMethod::FencedWallClock:
            return "glFinish + wall clock";
        case TimingMethod::Off:
            return "off";
    }
    return "off";
}

bool isSoftwareRenderer(std::string_view renderer) {
    for (std::string_view marker :
         {"llvmpipe", "softpipe", "SwiftShader", "Software Rasterizer", "lavapipe"}) {
        if (renderer.find(marker) != std::string_view::npos) return true;
    }
    return false;
}

PassTimer::PassTimer(TimingMode requested, std::string_view renderer) {
    switch (requested) {
        case TimingMode::Gpu:
            method_ = TimingMethod::GpuTimestamps;
            reason_ = "--timing gpu";
            break;
        case TimingMode::Fenced:
            method_ = TimingMethod::FencedWallClock;
            reason_ = "--timing fenced";
            break;
        case TimingMode::Off:
            method_ = TimingMethod::Off;
            reason_ = "--timing off";
            break;
        case TimingMode::Automatic:
            if (isSoftwareRenderer(renderer)) {
                method_ = TimingMethod::FencedWallClock;
                reason_ = cat("auto: ", renderer,
                              " is a software renderer; its timer queries do not measure rasterisation");
            } else {
                method_ = TimingMethod::GpuTimestamps;
                reason_ = "auto: hardware renderer";
            }
            break;
    }
}

gl::QueryName PassTimer::takeQuery() {
    if (!spareQueries_.empty()) {
        gl::QueryName q = std::move(spareQueries_.back());
        spareQueries_.pop_back();
        return q;
    }
    return gl::createQuery(GL_TIMESTAMP, "pass timer");
}

void PassTimer::beginFrame() {
    if (method_ != TimingMethod::GpuTimestamps) return;
    // Results arrive in submission order; stop at the first one that is not ready.
    std::size_t done = 0;
    for (; done < inFlight_.size(); ++done) {
        GLint available = GL_FALSE;
        glGetQueryObjectiv(inFlight_[done].stop.name(), GL_QUERY_RESULT_AVAILABLE, &available);
        if (available != GL_TRUE) break;
        GLuint64 start = 0, stop = 0;
        glGetQueryObjectui64v(inFlight_[done].start.name(), GL_QUERY_RESULT, &start);
        glGetQueryObjectui64v(inFlight_[done].stop.name(), GL_QUERY_RESULT, &stop);
        latest_[inFlight_[done].pass] = stop > start ? double(stop - start) * 1e-6 : 0.0;
    }
    for (std::size_t i = 0; i < done; ++i) {
        spareQueries_.push_back(std::move(inFlight_[i].start));
        spareQueries_.push_back(std::move(inFlight_[i].stop));
    }
    inFlight_.erase(inFlight_.begin(), inFlight_.begin() + static_cast<std::ptrdiff_t>(done));
    // A driver that never answers must not make the list grow forever.
    if (inFlight_.size() > 1024) inFlight_.erase(inFlight_.begin(), inFlight_.begin() + 512);
}

void PassTimer::begin(const std::string& pass) {
    switch (method_) {
        case TimingMethod::GpuTimestamps: {
            InFlight f{pass, takeQuery(), takeQuery()};
            glQueryCounter(f.start.name(), GL_TIMESTAMP);
            open_ = std::move(f);
            break;
        }
        case TimingMethod::FencedWallClock:
            timingFence("timing fence before the pass (glFinish: --timing fenced)");  // earlier work is not
                                                                                      // billed to it
            wallStart_ = std::chrono::steady_clock::now();
            break;
        case TimingMethod::Off:
            break;
    }
}

void PassTimer::end(const std::string& pass) {
    switch (method_) {
        case TimingMethod::GpuTimestamps:
            if (open_ && open_->pass == pass) {
                glQueryCounter(open_->stop.name(), GL_TIMESTAMP);
                inFlight_.push_back(std::move(*open_));
                open_.reset();
            }
            break;
        case TimingMethod::FencedWallClock: {
            timingFence("timing fence after the pass (glFinish: --timing fenced)");
            auto elapsed = std::chrono::steady_clock::now() - wallStart_;
            latest_[pass] = std::chrono::duration<double, std::milli>(elapsed).count();
            break;
        }
        case TimingMethod::Off:
            break;
    }
}

std::optional<double> PassTimer::latestMs(const std::string& pass) const {
    auto it = latest_.find(pass);
    if (it == latest_.end()) return std::nullopt;
    return it->second;
}

}  // namespace fx
