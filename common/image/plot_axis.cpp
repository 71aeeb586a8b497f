#include "image/plot_axis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace fx {
namespace {

// printf writes exponents as "e-06" and "e+06"; a tick label reads better as "e-6" and "e6".
std::string compactExponent(std::string text) {
    const std::size_t e = text.find('e');
    if (e == std::string::npos) return text;
    std::string mantissa = text.substr(0, e), exponent = text.substr(e + 1);
    const bool negative = !exponent.empty() && exponent[0] == '-';
    if (!exponent.empty() && (exponent[0] == '-' || exponent[0] == '+')) exponent.erase(0, 1);
    const std::size_t firstDigit = std::min(exponent.find_first_not_of('0'), exponent.size() - 1);
    return mantissa + "e" + (negative ? "-" : "") + exponent.substr(firstDigit);
}

}  // namespace

double PlotAxis::fraction(double value) const {
    if (logarithmic) {
        const double span = std::log10(high) - std::log10(low);
        return (std::log10(value) - std::log10(low)) / span;
    }
    return (value - low) / (high - low);
}

double niceStep(double roughStep) {
    const double decade = std::pow(10.0, std::floor(std::log10(roughStep)));
    const double mantissa = roughStep / decade;  // in [1, 10)
    // Thresholds at the geometric means between the candidates, so the closest one (by ratio) wins.
    if (mantissa < 1.4142) return decade;
    if (mantissa < 3.1623) return 2.0 * decade;
    if (mantissa < 7.0711) return 5.0 * decade;
    return 10.0 * decade;
}

std::string formatTick(double value, double step) {
    char text[32];
    // Snap values that should be zero but carry rounding noise (3 * 0.1 - 0.3), and -0.
    if (std::abs(value) < step * 1e-9) value = 0.0;
    const double magnitude = std::max(std::abs(value), step);
    if (magnitude >= 1e6 || step < 1e-4) {
        std::snprintf(text, sizeof text, "%g", value);
        return compactExponent(text);
    }
    const int decimals = std::max(0, static_cast<int>(-std::floor(std::log10(step) + 1e-9)));
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    return text;
}

std::string formatValue(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", value);
    return compactExponent(text);
}

PlotAxis makeLinearAxis(double dataMin, double dataMax, int targetTicks) {
    if (dataMin > dataMax) std::swap(dataMin, dataMax);
    double span = dataMax - dataMin;
    if (!(span > 0.0)) {
        // One value: show a range around it, 20% of its size (or +-1 around zero).
        const double half = dataMin != 0.0 ? std::abs(dataMin) * 0.1 : 1.0;
        dataMin -= half;
        dataMax += half;
        span = dataMax - dataMin;
    }
    PlotAxis axis;
    axis.low = dataMin - span * 0.06;
    axis.high = dataMax + span * 0.06;
    const double step = niceStep((axis.high - axis.low) / std::max(targetTicks, 2));
    // Ticks are counted in whole steps so that rounding does not accumulate; the count is bounded
    // in case the range is too narrow for double precision to step through.
    const double firstIndex = std::ceil(axis.low / step);
    for (int i = 0; i <= 50; ++i) {
        const double tick = (firstIndex + i) * step;
        if (tick > axis.high + step * 1e-9) break;
        axis.ticks.push_back(tick);
        axis.tickLabels.push_back(formatTick(tick, step));
    }
    return axis;
}

PlotAxis makeLogAxis(double dataMin, double dataMax) {
    if (dataMin > dataMax) std::swap(dataMin, dataMax);
    double lowExponent = std::log10(dataMin), highExponent = std::log10(dataMax);
    if (highExponent - lowExponent < 1.0) {
        // Less than a decade of data: widen to one decade centred on it, so some ticks show.
        const double middle = (lowExponent + highExponent) / 2.0;
        lowExponent = middle - 0.5;
        highExponent = middle + 0.5;
    }
    const double margin = (highExponent - lowExponent) * 0.06;
    PlotAxis axis;
    axis.logarithmic = true;
    axis.low = std::pow(10.0, lowExponent - margin);
    axis.high = std::pow(10.0, highExponent + margin);

    const int firstDecade = static_cast<int>(std::floor(lowExponent - margin));
    const int lastDecade = static_cast<int>(std::ceil(highExponent + margin));
    const int decades = lastDecade - firstDecade;
    // Every power of ten up to 6 decades, then every second, third, ...: at most about 8 labels.
    const int every = std::max(1, (decades + 5) / 6);
    // Between powers of ten only when there are few of them.
    const std::vector<double> multiples =
        decades <= 3 ? std::vector<double>{1, 2, 5} : std::vector<double>{1};
    for (int e = firstDecade; e <= lastDecade; ++e) {
        if (e % every != 0) continue;
        const double power = std::pow(10.0, e);
        for (double m : multiples) {
            const double tick = m * power;
            if (tick < axis.low || tick > axis.high) continue;
            axis.ticks.push_back(tick);
            axis.tickLabels.push_back(formatTick(tick, power));
        }
    }
    return axis;
}

}  // namespace fx
