#include "app/picture_scale.hpp"

#include <algorithm>
#include <cmath>

#include "base/log.hpp"

namespace fx {
namespace {

// Scales are whole multiples of 5%, so a steady renderer settles on one and the textures of the
// frame graph keep their size from frame to frame.
constexpr double kQuantum = 0.05;
constexpr double kSmallest = 0.10;
// Aim below the budget, so that a frame's noise does not push it over; grow only when the larger
// picture would still be well inside it.
constexpr double kAim = 0.75;
constexpr double kGrowBelow = 0.6;
constexpr int kSamples = 3;

double quantizeDown(double scale) {
    return std::clamp(std::floor(scale / kQuantum + 1e-6) * kQuantum, kSmallest, 1.0);
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

}  // namespace

std::string percentText(double scale) {
    return cat(int(std::lround(scale * 100.0)), "%");
}

PictureScale::PictureScale(std::optional<double> pinned, double budgetMs)
    : pinned_(pinned), budgetMs_(budgetMs), scale_(pinned ? std::clamp(*pinned, 0.01, 1.0) : 1.0) {}

Size2D PictureScale::rendered(Size2D place) const {
    if (place.empty()) return {};
    return {std::max(1, int(std::lround(place.width * scale_))),
            std::max(1, int(std::lround(place.height * scale_)))};
}

void PictureScale::setScale(double scale) {
    if (scale == scale_) return;
    scale_ = scale;
    samples_.clear();
    settle_ = 1;
}

void PictureScale::restart() {
    samples_.clear();
    settle_ = 1;
}

std::string PictureScale::cycle() {
    if (!pinned_) {
        pinned_ = 1.0;
    } else if (*pinned_ > 0.5) {
        pinned_ = 0.5;
    } else if (*pinned_ > 0.25) {
        pinned_ = 0.25;
    } else {
        pinned_.reset();
    }
    setScale(pinned_ ? *pinned_ : scale_);
    return pinned_ ? cat("picture scale pinned at ", percentText(*pinned_))
                   : cat("picture scale automatic (frame budget ", int(budgetMs_), " ms)");
}

void PictureScale::frameTook(double ms) {
    if (pinned_ || !(ms >= 0)) return;
    if (settle_ > 0) {
        --settle_;
        return;
    }
    samples_.push_back(ms);
    // Far over the budget: give way at once, by the share of pixels that would bring the frame to the
    // aim if all of it were pixels (it is not, so the next frames may take it down further).
    const bool farOver = ms > 2.0 * budgetMs_;
    if (!farOver && int(samples_.size()) < kSamples) return;
    const double typical = farOver ? ms : median(samples_);
    if (typical > budgetMs_) {
        const double wanted = scale_ * std::sqrt(kAim * budgetMs_ / typical);
        setScale(std::min(quantizeDown(wanted), std::max(scale_ - kQuantum, kSmallest)));
    } else if (scale_ < 1.0) {
        // Up to the largest scale whose frame, were all of it pixels (the worst case), stays well inside:
        // a cheap step after a slow one gets its picture back in a frame or two, not fifty.
        double larger = scale_;
        for (double next = std::min(1.0, scale_ + kQuantum); next <= 1.0 + 1e-9; next += kQuantum) {
            if (typical * (next * next) / (scale_ * scale_) >= kGrowBelow * budgetMs_) break;
            larger = std::min(next, 1.0);
        }
        setScale(larger);
    }
    if (samples_.size() > std::size_t(kSamples)) samples_.erase(samples_.begin());
}

std::string PictureScale::notice(Size2D place) const {
    if (scale_ >= 1.0 || place.empty()) return {};
    const Size2D r = rendered(place);
    const std::string size = cat(place.width, "x", place.height, " (", r.width, "x", r.height, ")");
    if (pinned_) return cat("picture at ", percentText(scale_), " of ", size, ", pinned (F6 changes it)");
    return cat("picture at ", percentText(scale_), " of ", size, ": slow renderer, frame budget ",
               int(budgetMs_), " ms (F6 pins the scale)");
}

}  // namespace fx
