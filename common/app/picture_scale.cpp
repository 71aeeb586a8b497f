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
    measured_.clear();
    notPixels_ = false;
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

PictureScale::Cost PictureScale::cost() const {
    // frame = fixed + pixels * scale^2, fitted by least squares to the scales measured in this step
    // (one scale alone: all of the frame is taken for pixels, the case a smaller picture helps most).
    Cost c;
    const std::size_t n = measured_.size();
    if (n == 0) return c;
    if (n == 1) {
        c.pixels = measured_[0].ms / (measured_[0].scale * measured_[0].scale);
        return c;
    }
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (const Measured& m : measured_) {
        const double x = m.scale * m.scale;
        sx += x, sy += m.ms, sxx += x * x, sxy += x * m.ms;
    }
    const double d = double(n) * sxx - sx * sx;
    c.pixels = d > 0 ? (double(n) * sxy - sx * sy) / d : 0.0;
    c.fixed = (sy - c.pixels * sx) / double(n);
    if (c.pixels < 0 || c.fixed < 0) {
        // Noise larger than what the picture's size changes: read it as a fixed cost, no pixels.
        c.pixels = std::max(c.pixels, 0.0);
        c.fixed = std::max(sy / double(n) - c.pixels * sx / double(n), 0.0);
    }
    return c;
}

void PictureScale::remember(double typical) {
    // The same scale measured again, far from what it took before: the work changed (a parameter,
    // another inspected texture), and the other scales' times no longer describe it.
    for (const Measured& m : measured_) {
        if (std::abs(m.scale - scale_) < 1e-9 && std::abs(typical - m.ms) > 0.3 * std::max(m.ms, 1.0)) {
            measured_.clear();
            break;
        }
    }
    std::erase_if(measured_, [this](const Measured& m) { return std::abs(m.scale - scale_) < 1e-9; });
    measured_.push_back({scale_, typical});
    if (measured_.size() > 4) measured_.erase(measured_.begin());
}

void PictureScale::frameTook(double ms) {
    if (pinned_ || !(ms >= 0)) return;
    if (settle_ > 0) {
        --settle_;
        return;
    }
    samples_.push_back(ms);
    // Far over the budget: give way at once; otherwise decide on the median of a few frames.
    const bool farOver = ms > 2.0 * budgetMs_;
    if (!farOver && int(samples_.size()) < kSamples) return;
    const double typical = farOver ? ms : median(samples_);
    remember(typical);
    const Cost c = cost();
    const double aim = kAim * budgetMs_;
    // The smallest picture worth having: below it the pixels are under a tenth of the frame, and a
    // frame whose time is not in its pixels would lose its picture for nothing.
    const double worthwhile = c.pixels > 0 ? std::sqrt(std::min(1.0, 0.1 * c.fixed / c.pixels)) : 1.0;
    notPixels_ = c.fixed >= aim;
    if (typical > budgetMs_) {
        double wanted = c.fixed < aim && c.pixels > 0 ? std::sqrt((aim - c.fixed) / c.pixels) : worthwhile;
        wanted = std::max(wanted, worthwhile);
        // Down by at least one step while the model says it helps; never below the smallest worth having.
        double next = quantizeDown(wanted);
        if (next >= scale_ && !notPixels_) next = std::max(scale_ - kQuantum, kSmallest);
        if (notPixels_) next = std::max(next, quantizeDown(worthwhile));
        setScale(std::clamp(next, kSmallest, 1.0));
    } else if (scale_ < 1.0) {
        // Up to the largest scale whose frame the model keeps well inside the budget: a cheap step after a
        // slow one gets its picture back in a frame or two, not fifty.
        double larger = scale_;
        for (double next = std::min(1.0, scale_ + kQuantum); next <= 1.0 + 1e-9; next += kQuantum) {
            if (c.fixed + c.pixels * next * next >= kGrowBelow * budgetMs_) break;
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
    if (notPixels_)
        return cat(
            "picture at ", percentText(scale_), " of ", size,
            ": slow renderer; most of this step's frame is not in its pixels, so a smaller picture would not bring it within the ",
            int(budgetMs_), " ms budget (F6 pins the scale)");
    return cat("picture at ", percentText(scale_), " of ", size, ": slow renderer, frame budget ",
               int(budgetMs_), " ms (F6 pins the scale)");
}

}  // namespace fx
