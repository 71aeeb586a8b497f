// Keyframe sampling against values worked out by hand: linear, step and cubic-spline keys, times before
// the first key and after the last, keys at the same time, and clip time that loops for hours.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include <glm/gtc/quaternion.hpp>

#include "scene/animation.hpp"

namespace {

using fx::AnimatedProperty;
using fx::AnimationChannel;
using fx::Interpolation;

AnimationChannel channel(AnimatedProperty property, Interpolation interpolation, std::vector<float> times,
                         std::vector<glm::vec4> values) {
    AnimationChannel c;
    c.node = 0;
    c.property = property;
    c.interpolation = interpolation;
    c.times = std::move(times);
    c.values = std::move(values);
    return c;
}

void expectNear(const glm::vec4& actual, const glm::vec4& expected, float tolerance = 1e-6f) {
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(actual[i], expected[i], tolerance) << "component " << i;
}

// Translation keys at 0, 1 and 3 s: (0,0,0) -> (2,4,6) -> (4,0,0).
AnimationChannel translationKeys(Interpolation interpolation) {
    return channel(AnimatedProperty::translation, interpolation, {0.0f, 1.0f, 3.0f},
                   {{0, 0, 0, 0}, {2, 4, 6, 0}, {4, 0, 0, 0}});
}

TEST(AnimationSampling, LinearBetweenKeys) {
    auto c = translationKeys(Interpolation::linear);
    expectNear(fx::sampleChannel(c, 0.5f), {1, 2, 3, 0});
    expectNear(fx::sampleChannel(c, 2.0f), {3, 2, 3, 0});  // halfway through the 2 s interval
    expectNear(fx::sampleChannel(c, 2.5f), {3.5f, 1, 1.5f, 0});
}

TEST(AnimationSampling, ExactlyOnKeysIncludingTheLast) {
    auto c = translationKeys(Interpolation::linear);
    expectNear(fx::sampleChannel(c, 0.0f), {0, 0, 0, 0});
    expectNear(fx::sampleChannel(c, 1.0f), {2, 4, 6, 0});
    expectNear(fx::sampleChannel(c, 3.0f), {4, 0, 0, 0});
}

TEST(AnimationSampling, BeforeTheFirstAndAfterTheLastKeyHold) {
    auto c = translationKeys(Interpolation::linear);
    expectNear(fx::sampleChannel(c, -5.0f), {0, 0, 0, 0});
    expectNear(fx::sampleChannel(c, 3.5f), {4, 0, 0, 0});
    expectNear(fx::sampleChannel(c, 1e30f), {4, 0, 0, 0});
    expectNear(fx::sampleChannel(c, std::numeric_limits<float>::infinity()), {4, 0, 0, 0});
    // A NaN time is treated as "before the start", not spread into the pose.
    expectNear(fx::sampleChannel(c, std::numeric_limits<float>::quiet_NaN()), {0, 0, 0, 0});
}

TEST(AnimationSampling, StepHoldsEachKeyUntilTheNext) {
    auto c = translationKeys(Interpolation::step);
    expectNear(fx::sampleChannel(c, 0.0f), {0, 0, 0, 0});
    expectNear(fx::sampleChannel(c, 0.999f), {0, 0, 0, 0});
    expectNear(fx::sampleChannel(c, 1.0f), {2, 4, 6, 0});
    expectNear(fx::sampleChannel(c, 2.999f), {2, 4, 6, 0});
    expectNear(fx::sampleChannel(c, 3.0f), {4, 0, 0, 0});  // the last key
    expectNear(fx::sampleChannel(c, 100.0f), {4, 0, 0, 0});
}

TEST(AnimationSampling, RotationSlerpsAndIsNormalised) {
    glm::quat a = glm::angleAxis(0.0f, glm::vec3(0, 1, 0));
    glm::quat b = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 1, 0));
    auto c = channel(AnimatedProperty::rotation, Interpolation::linear, {0.0f, 1.0f},
                     {{a.x, a.y, a.z, a.w}, {b.x, b.y, b.z, b.w}});
    // Halfway: 45 degrees about Y, (0, sin 22.5, 0, cos 22.5).
    float half = glm::radians(22.5f);
    expectNear(fx::sampleChannel(c, 0.5f), {0, std::sin(half), 0, std::cos(half)}, 1e-6f);
    // A quarter of the way: 22.5 degrees (slerp has constant angular speed; nlerp would not).
    float quarter = glm::radians(11.25f);
    expectNear(fx::sampleChannel(c, 0.25f), {0, std::sin(quarter), 0, std::cos(quarter)}, 1e-6f);
}

TEST(AnimationSampling, RotationTakesTheShortWayRound) {
    // The second key is stored negated: the same orientation. Sampling between must not spin round.
    glm::quat b = glm::angleAxis(glm::radians(20.0f), glm::vec3(1, 0, 0));
    auto c = channel(AnimatedProperty::rotation, Interpolation::linear, {0.0f, 1.0f},
                     {{0, 0, 0, 1}, {-b.x, -b.y, -b.z, -b.w}});
    glm::quat mid = fx::toQuat(fx::sampleChannel(c, 0.5f));
    float angle = glm::degrees(2.0f * std::acos(std::min(1.0f, std::abs(mid.w))));
    EXPECT_NEAR(angle, 10.0f, 1e-3f);
}

TEST(AnimationSampling, UnnormalisedAndZeroQuaternionsAreSafe) {
    auto c =
        channel(AnimatedProperty::rotation, Interpolation::step, {0.0f, 1.0f}, {{0, 0, 0, 2}, {0, 0, 0, 0}});
    expectNear(fx::sampleChannel(c, 0.5f), {0, 0, 0, 1});
    expectNear(fx::sampleChannel(c, 1.0f), {0, 0, 0, 1});  // zero quaternion: the identity, not NaN
}

TEST(AnimationSampling, CubicSplineUsesHermiteBasis) {
    // Keys 0 -> 1 over [0, 2] s. Stored per key: in-tangent, value, out-tangent.
    auto flat = channel(AnimatedProperty::translation, Interpolation::cubicSpline, {0.0f, 2.0f},
                        {{0, 0, 0, 0}, {0, 0, 0, 0}, {0, 0, 0, 0}, {0, 0, 0, 0}, {1, 1, 1, 0}, {0, 0, 0, 0}});
    // Zero tangents: h(u) = 3u^2 - 2u^3; at u = 0.25 that is 0.15625.
    EXPECT_NEAR(fx::sampleChannel(flat, 0.5f).x, 0.15625f, 1e-6f);
    EXPECT_NEAR(fx::sampleChannel(flat, 1.0f).x, 0.5f, 1e-6f);
    // Tangents of 0.5 per second (the straight line's slope) reproduce the straight line.
    auto straight = flat;
    straight.values[2] = {0.5f, 0, 0, 0};  // out-tangent of key 0
    straight.values[3] = {0.5f, 0, 0, 0};  // in-tangent of key 1
    EXPECT_NEAR(fx::sampleChannel(straight, 0.5f).x, 0.25f, 1e-6f);
    EXPECT_NEAR(fx::sampleChannel(straight, 1.5f).x, 0.75f, 1e-6f);
    EXPECT_NEAR(fx::sampleChannel(straight, 2.0f).x, 1.0f, 1e-6f);
}

TEST(AnimationSampling, KeysAtTheSameTimeDoNotDivideByZero) {
    auto c = channel(AnimatedProperty::translation, Interpolation::linear, {0.0f, 1.0f, 1.0f, 2.0f},
                     {{0, 0, 0, 0}, {1, 0, 0, 0}, {5, 0, 0, 0}, {6, 0, 0, 0}});
    expectNear(fx::sampleChannel(c, 0.5f), {0.5f, 0, 0, 0});
    expectNear(fx::sampleChannel(c, 1.0f), {5, 0, 0, 0});  // the later key wins at the jump
    expectNear(fx::sampleChannel(c, 1.5f), {5.5f, 0, 0, 0});
}

TEST(AnimationSampling, ChannelsWithoutKeysGiveNeutralValues) {
    expectNear(fx::sampleChannel(channel(AnimatedProperty::translation, Interpolation::linear, {}, {}), 1.0f),
               {0, 0, 0, 0});
    expectNear(fx::sampleChannel(channel(AnimatedProperty::rotation, Interpolation::linear, {}, {}), 1.0f),
               {0, 0, 0, 1});
    expectNear(fx::sampleChannel(channel(AnimatedProperty::scale, Interpolation::linear, {}, {}), 1.0f),
               {1, 1, 1, 0});
}

TEST(ClipTime, LoopsInsideTheClip) {
    EXPECT_FLOAT_EQ(fx::clipTime(0.25, 1.0f), 0.25f);
    EXPECT_FLOAT_EQ(fx::clipTime(2.5, 1.0f), 0.5f);
    EXPECT_FLOAT_EQ(fx::clipTime(1.0, 1.0f), 0.0f);  // the end of one loop is the start of the next
    EXPECT_FLOAT_EQ(fx::clipTime(7.0, 2.0f), 1.0f);
}

TEST(ClipTime, NegativePlaybackRunsBackwards) {
    EXPECT_FLOAT_EQ(fx::clipTime(-0.25, 1.0f), 0.75f);
    EXPECT_FLOAT_EQ(fx::clipTime(-2.0, 1.5f), 1.0f);
}

TEST(ClipTime, FarPastTheLengthStaysExactAndSmall) {
    // A month of playback at 60 fps: the wrapped time is exact, not a float that lost its fraction.
    double seconds = 30.0 * 24 * 3600 + 0.375;
    EXPECT_FLOAT_EQ(fx::clipTime(seconds, 1.0f), 0.375f);
    float t = fx::clipTime(1e15 + 0.5, 1.0f);
    EXPECT_GE(t, 0.0f);
    EXPECT_LT(t, 1.0f);
    EXPECT_FLOAT_EQ(t, 0.5f);
    t = fx::clipTime(1e300, 0.7f);
    EXPECT_TRUE(std::isfinite(t));
    EXPECT_GE(t, 0.0f);
    EXPECT_LT(t, 0.7f);
}

TEST(ClipTime, DegenerateInputsGiveZero) {
    EXPECT_EQ(fx::clipTime(5.0, 0.0f), 0.0f);
    EXPECT_EQ(fx::clipTime(5.0, -1.0f), 0.0f);
    EXPECT_EQ(fx::clipTime(std::numeric_limits<double>::infinity(), 1.0f), 0.0f);
    EXPECT_EQ(fx::clipTime(std::numeric_limits<double>::quiet_NaN(), 1.0f), 0.0f);
    EXPECT_EQ(fx::clipTime(1.0, std::numeric_limits<float>::quiet_NaN()), 0.0f);
}

TEST(ApplyClip, WritesEachPropertyOfItsNode) {
    fx::AnimationClip clip;
    clip.channels.push_back(translationKeys(Interpolation::linear));
    auto rotation = channel(AnimatedProperty::rotation, Interpolation::step, {0.0f}, {{0, 1, 0, 0}});
    rotation.node = 1;
    clip.channels.push_back(rotation);
    auto scale =
        channel(AnimatedProperty::scale, Interpolation::linear, {0.0f, 2.0f}, {{1, 1, 1, 0}, {3, 3, 3, 0}});
    scale.node = 1;
    clip.channels.push_back(scale);
    auto stray = translationKeys(Interpolation::linear);
    stray.node = 7;  // no such node: ignored
    clip.channels.push_back(stray);

    std::vector<fx::NodeTransform> pose(2);
    fx::applyClip(clip, 1.0f, pose);
    EXPECT_EQ(pose[0].translation, glm::vec3(2, 4, 6));
    EXPECT_EQ(pose[0].scale, glm::vec3(1));
    EXPECT_NEAR(std::abs(pose[1].rotation.y), 1.0f, 1e-6f);
    EXPECT_EQ(pose[1].scale, glm::vec3(2));
    EXPECT_EQ(pose[1].translation, glm::vec3(0));
}

TEST(NodeTransform, MatrixIsTranslateRotateScale) {
    fx::NodeTransform t;
    t.translation = {1, 2, 3};
    t.rotation = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 0, 1));
    t.scale = {2, 2, 2};
    // (1, 0, 0) -> scaled (2, 0, 0) -> rotated 90 about Z (0, 2, 0) -> moved (1, 4, 3).
    glm::vec4 p = t.matrix() * glm::vec4(1, 0, 0, 1);
    EXPECT_NEAR(p.x, 1.0f, 1e-6f);
    EXPECT_NEAR(p.y, 4.0f, 1e-6f);
    EXPECT_NEAR(p.z, 3.0f, 1e-6f);
}

}  // namespace
