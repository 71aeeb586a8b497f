#include "app/picture_scale.hpp"

#include <algorithm>
#include <cmath>

#include "base/log.hpp"

namespace fx {
namespace {

// Scales are whole multiples of 5%, so a steady renderer settles on one and the textures of the
// frame graph keep their size from frame to frame.
constexpr double kQuantum = 0.05;
// A pinned scale may be anything from 1%; an automatic one never goes below half the place's width and
// height: below that the picture is a blur, whatever the frame gains.
constexpr double kSmallest = 0.01;
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

double PictureScale::chooseScale(const Cost& c) const {
    // The frame the model expects at a scale; the scales worth having are on the grid from the
    // smallest an automatic scale goes to up to the whole picture.
    auto predicted = [&c](double scale) { return c.fixed + c.pixels * scale * scale; };
    const double full = predicted(1.0);
    const double aim = kAim * budgetMs_;
    const int steps = int(std::lround((1.0 - kSmallestAutomatic) / kQuantum));
    // The largest scale whose frame is within the aim.
    for (int i = 0; i <= steps; ++i) {
        const double scale = quantizeDown(1.0 - i * kQuantum);
        if (predicted(scale) <= aim) return scale;
    }
    // None is: the smallest scale answers soonest, and it is worth its blur only when it at least halves
    // the whole picture's frame; otherwise the picture stays whole (the drop would buy nothing).
    return predicted(kSmallestAutomatic) <= 0.5 * full ? kSmallestAutomatic : 1.0;
}

void PictureScale::frameTook(double ms) {
    if (pinned_ || held_ || !(ms >= 0)) return;
    if (settle_ > 0) {
        --settle_;
        return;
    }
    samples_.push_back(ms);
    // Far over the budget: give way at once; otherwise decide on the median of a few frames.
    const bool farOver = ms > 2.0 * budgetMs_;
    if (!farOver && int(samples_.size()) < kSamples) return;
    const double typical = farOver ? ms : median(samples_);
    lastTypical_ = typical;
    remember(typical);
    const Cost c = cost();
    const double chosen = chooseScale(c);
    // Over the budget however small the picture (within the smallest worth having): the time is not in
    // the pixels, and the notice says so.
    notPixels_ = c.fixed + c.pixels * kSmallestAutomatic * kSmallestAutomatic > kAim * budgetMs_;
    if (typical > budgetMs_) {
        // Down to what pays (or back up when the scale tried showed that it does not).
        setScale(chosen);
    } else if (scale_ < 1.0) {
        // Up to the largest scale whose frame the model keeps well inside the budget: a cheap step after a
        // slow one gets its picture back in a frame or two, not fifty.
        double larger = scale_;
        for (double next = std::min(1.0, scale_ + kQuantum); next <= 1.0 + 1e-9; next += kQuantum) {
            if (c.fixed + c.pixels * next * next >= kGrowBelow * budgetMs_) break;
            larger = std::min(next, 1.0);
        }
        setScale(std::max(larger, chosen));
    }
    if (samples_.size() > std::size_t(kSamples)) samples_.erase(samples_.begin());
}

std::string PictureScale::notice(Size2D place) const {
    if (place.empty()) return {};
    const Size2D r = rendered(place);
    const std::string picture = cat("picture at ", percentText(scale_), " of ", place.width, "x",
                                    place.height, " (", r.width, "x", r.height, ")");
    if (pinned_) return scale_ < 1.0 ? cat(picture, ", pinned (F6 changes it)") : std::string();
    const bool over = lastTypical_ > budgetMs_;
    if (!over && scale_ >= 1.0) return {};
    if (!over)
        return cat(picture, ": slow renderer, frame budget ", int(budgetMs_), " ms (F6 pins the scale)");
    // Over the budget at the scale that pays best: say what the frame costs and where the time is.
    const Cost c = cost();
    const std::string frame = cat("this step's frame takes ", int(std::lround(lastTypical_)), " ms, about ",
                                  int(std::lround(c.fixed)), " ms of it whatever the picture's size");
    if (scale_ >= 1.0)
        return cat(
            frame, ": a smaller picture would not bring it within the ", int(budgetMs_),
            " ms budget, so the picture stays whole; keys and clicks wait in order (F6 pins the scale)");
    return cat(picture, ": ", frame, "; keys and clicks wait in order (F6 pins the scale)");
}

}  // namespace fx
