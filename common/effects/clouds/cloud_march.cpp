#include "effects/clouds/cloud_march.hpp"

#include <algorithm>
#include <cmath>

namespace fx {
double wrapUnit(double v) {
    double w = v - std::floor(v);
    return w >= 1.0 ? 0.0 : w;  // floor of a value just below an integer can round w up to 1
}

CloudScroll::CloudScroll(glm::dvec4 start) {
    for (int i = 0; i < 4; ++i) offset_[i] = std::isfinite(start[i]) ? wrapUnit(start[i]) : 0.0;
}

void CloudScroll::advance(const glm::dvec4& speedPerSecond, double seconds) {
    if (!std::isfinite(seconds)) return;
    for (int i = 0; i < 4; ++i) {
        if (!std::isfinite(speedPerSecond[i])) continue;
        // The product alone is wrapped first, so a huge time step cannot carry the sum past double's
        // spacing either.
        offset_[i] = wrapUnit(offset_[i] + wrapUnit(speedPerSecond[i] * seconds));
    }
}

CloudScroll CloudScroll::at(const glm::dvec4& start, const glm::dvec4& speedPerSecond, double seconds) {
    CloudScroll s(start);
    s.advance(speedPerSecond, seconds);
    return s;
}

glm::vec4 unwrappedCloudOffsetStep(const glm::vec4& offset, const glm::vec4& speedPerSecond, float seconds) {
    return offset + speedPerSecond * seconds;
}

CloudMarch cloudMarch(float bottom, float top, float steps, float threshold) {
    CloudMarch m;
    m.bottom = std::isfinite(bottom) ? bottom : 0.0f;
    m.top = std::isfinite(top) ? top : m.bottom;
    float count = std::isfinite(steps) ? std::floor(std::clamp(steps, 0.0f, float(kCloudMaxSteps))) : 0.0f;
    m.steps = int(count);
    float thickness = m.top - m.bottom;
    m.stepHeight = (m.steps > 0 && thickness > 0.0f) ? thickness / float(m.steps) : 0.0f;
    m.threshold = std::isnan(threshold) ? 1.0f : std::max(threshold, 0.0f);
    m.thresholdGain = m.threshold < 1.0f ? 1.0f / (1.0f - m.threshold) : 0.0f;
    if (!std::isfinite(m.thresholdGain)) m.thresholdGain = 0.0f;
    m.drawn = m.steps > 0 && thickness > 0.0f;
    m.thresholdClears = m.thresholdGain <= 0.0f;
    return m;
}

float bayer4x4(int x, int y) {
    static constexpr int kMatrix[4][4] = {{0, 8, 2, 10}, {12, 4, 14, 6}, {3, 11, 1, 9}, {15, 7, 13, 5}};
    return float(kMatrix[y & 3][x & 3]) / 16.0f;
}

float interleavedGradientNoise(float x, float y, int frame) {
    float shift = 5.588238f * float(frame % 64);
    x += shift;
    y += shift;
    float f = 0.06711056f * x + 0.00583715f * y;
    f -= std::floor(f);
    float g = 52.9829189f * f;
    return g - std::floor(g);
}

}  // namespace fx
