#include "scene/animation.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace fx {
namespace {

glm::vec4 emptyValue(AnimatedProperty property) {
    switch (property) {
        case AnimatedProperty::translation:
            return glm::vec4(0.0f);
        case AnimatedProperty::rotation:
            return glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
        case AnimatedProperty::scale:
            return glm::vec4(1.0f, 1.0f, 1.0f, 0.0f);
    }
    return glm::vec4(0.0f);
}

glm::vec4 fromQuat(const glm::quat& q) {
    return {q.x, q.y, q.z, q.w};
}

// The key's value: for cubic splines the middle of the three stored values.
glm::vec4 keyValue(const AnimationChannel& c, std::size_t key) {
    std::size_t index = c.interpolation == Interpolation::cubicSpline ? key * 3 + 1 : key;
    return index < c.values.size() ? c.values[index] : emptyValue(c.property);
}

glm::vec4 tangent(const AnimationChannel& c, std::size_t key, bool out) {
    std::size_t index = key * 3 + (out ? 2 : 0);
    return index < c.values.size() ? c.values[index] : glm::vec4(0.0f);
}

glm::vec4 normalisedRotation(const glm::vec4& v) {
    return fromQuat(toQuat(v));
}

}  // namespace

glm::mat4 NodeTransform::matrix() const {
    glm::mat4 m = glm::translate(glm::mat4(1.0f), translation);
    m *= glm::mat4_cast(rotation);
    return glm::scale(m, scale);
}

glm::quat toQuat(const glm::vec4& xyzw) {
    float length = std::sqrt(glm::dot(xyzw, xyzw));
    if (!(length > 1e-12f)) return glm::quat(1.0f, 0.0f, 0.0f, 0.0f);  // zero or NaN: no rotation
    glm::vec4 n = xyzw / length;
    return glm::quat(n.w, n.x, n.y, n.z);
}

glm::vec4 sampleChannel(const AnimationChannel& c, float time) {
    std::size_t keys = c.times.size();
    if (keys == 0) return emptyValue(c.property);
    bool rotation = c.property == AnimatedProperty::rotation;
    auto finish = [&](const glm::vec4& v) { return rotation ? normalisedRotation(v) : v; };
    if (!(time > c.times.front())) return finish(keyValue(c, 0));  // before the first key, or NaN
    if (time >= c.times.back()) return finish(keyValue(c, keys - 1));

    // The key interval [k, k + 1] that holds `time`: times[k] <= time < times[k + 1].
    auto after = std::upper_bound(c.times.begin(), c.times.end(), time);
    std::size_t k1 = static_cast<std::size_t>(after - c.times.begin());
    std::size_t k0 = k1 - 1;
    float t0 = c.times[k0], t1 = c.times[k1];
    float span = t1 - t0;
    if (c.interpolation == Interpolation::step || !(span > 0.0f)) return finish(keyValue(c, k0));
    float u = std::clamp((time - t0) / span, 0.0f, 1.0f);

    if (c.interpolation == Interpolation::cubicSpline) {
        // Hermite basis; the stored tangents are per second, so they scale with the interval.
        float u2 = u * u, u3 = u2 * u;
        glm::vec4 p0 = keyValue(c, k0), p1 = keyValue(c, k1);
        glm::vec4 m0 = tangent(c, k0, true) * span, m1 = tangent(c, k1, false) * span;
        glm::vec4 v =
            (2 * u3 - 3 * u2 + 1) * p0 + (u3 - 2 * u2 + u) * m0 + (-2 * u3 + 3 * u2) * p1 + (u3 - u2) * m1;
        return finish(v);
    }
    glm::vec4 a = keyValue(c, k0), b = keyValue(c, k1);
    if (rotation) return fromQuat(glm::normalize(glm::slerp(toQuat(a), toQuat(b), u)));
    return a + (b - a) * u;
}

float clipTime(double playbackSeconds, float duration) {
    if (!(duration > 0.0f) || !std::isfinite(playbackSeconds)) return 0.0f;
    double d = duration;
    double t = std::fmod(playbackSeconds, d);  // exact for any double, keeps the sign of the input
    if (t < 0.0) t += d;
    // Rounding to float can land exactly on the duration; the loop starts again there.
    float result = static_cast<float>(t);
    return result < duration ? result : 0.0f;
}

void applyClip(const AnimationClip& clip, float time, std::vector<NodeTransform>& pose) {
    for (const AnimationChannel& channel : clip.channels) {
        if (channel.node < 0 || static_cast<std::size_t>(channel.node) >= pose.size()) continue;
        NodeTransform& node = pose[static_cast<std::size_t>(channel.node)];
        glm::vec4 v = sampleChannel(channel, time);
        switch (channel.property) {
            case AnimatedProperty::translation:
                node.translation = glm::vec3(v);
                break;
            case AnimatedProperty::rotation:
                node.rotation = toQuat(v);
                break;
            case AnimatedProperty::scale:
                node.scale = glm::vec3(v);
                break;
        }
    }
}

}  // namespace fx
