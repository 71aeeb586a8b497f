// The inspector's statistics on the GPU (ui/gpu_texture_stats.hpp) against the CPU's (analyseImage on
// the texture read back): the same counts, range, mean and histogram, on small textures with NaN,
// +-Inf, negative values, an HDR tail (a logarithmic histogram), 8-bit and half-float storage, a mip
// level, and depth shown as distance.
#include <cmath>
#include <limits>

#include "gl/readback.hpp"
#include "gl/texture.hpp"
#include "gl_test.hpp"
#include "render_gl/pass_timer.hpp"
#include "ui/gpu_texture_stats.hpp"

using namespace fx;

namespace {

constexpr float kNan = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

class GpuTextureStatsTest : public GlTest {
protected:
    void SetUp() override {
        GlTest::SetUp();
        stats = GpuTextureStats::create();
        ASSERT_TRUE(stats.usable());
    }

    // Both ways on one texture level; every number compared.
    void expectSame(const gl::Texture& texture, const TextureSpec& spec, int level,
                    bool linearDepth = false) {
        std::optional<TextureAnalysis> gpu =
            stats.analyse(texture.name(), spec, level, linearDepth, 0.1f, 50.0f);
        ASSERT_TRUE(gpu.has_value());
        TextureAnalysis cpu =
            analyseImage(gl::readTexture(texture.name(), spec, level), linearDepth, 0.1f, 50.0f);
        EXPECT_EQ(gpu->size.width, cpu.size.width);
        EXPECT_EQ(gpu->size.height, cpu.size.height);
        ASSERT_EQ(gpu->channels, cpu.channels);
        EXPECT_EQ(gpu->nanTexels, cpu.nanTexels);
        EXPECT_EQ(gpu->infTexels, cpu.infTexels);
        EXPECT_EQ(gpu->negativeTexels, cpu.negativeTexels);
        EXPECT_EQ(gpu->farPlaneTexels, cpu.farPlaneTexels);
        ASSERT_EQ(gpu->stats.size(), cpu.stats.size());
        for (std::size_t c = 0; c < cpu.stats.size(); ++c) {
            const ChannelStats &g = gpu->stats[c], &e = cpu.stats[c];
            EXPECT_EQ(g.finiteCount, e.finiteCount) << "channel " << c;
            EXPECT_EQ(g.nanCount, e.nanCount) << "channel " << c;
            EXPECT_EQ(g.infCount, e.infCount) << "channel " << c;
            EXPECT_EQ(g.negativeCount, e.negativeCount) << "channel " << c;
            EXPECT_FLOAT_EQ(g.min, e.min) << "channel " << c;
            EXPECT_FLOAT_EQ(g.max, e.max) << "channel " << c;
            EXPECT_NEAR(g.mean, e.mean, 1e-5 * std::max(1.0, std::abs(e.mean))) << "channel " << c;
        }
        const ValueHistogram &gh = gpu->histogram, &ch = cpu.histogram;
        EXPECT_EQ(gh.logarithmic, ch.logarithmic);
        EXPECT_FLOAT_EQ(gh.low, ch.low);
        EXPECT_FLOAT_EQ(gh.high, ch.high);
        EXPECT_EQ(gh.peak, ch.peak);
        for (int c = 0; c < cpu.channels; ++c)
            EXPECT_EQ(gh.counts[std::size_t(c)], ch.counts[std::size_t(c)]) << c;
    }

    GpuTextureStats stats;
};

gl::Texture upload(TextureFormat format, int width, int height, const std::vector<float>& rgba,
                   int levels = 1) {
    gl::Texture t = gl::Texture::create2D(format, width, height, levels, "test.stats");
    glTextureSubImage2D(t.name(), 0, 0, 0, width, height, GL_RGBA, GL_FLOAT, rgba.data());
    if (levels > 1) glGenerateTextureMipmap(t.name());
    return t;
}

// A 13x7 picture (odd sizes: partial workgroups) with a value per texel from a few integer hashes.
std::vector<float> pattern(int width, int height, float scale) {
    std::vector<float> v;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            unsigned h = unsigned(x) * 73856093u ^ unsigned(y) * 19349663u;
            for (int c = 0; c < 4; ++c)
                v.push_back(scale * float((h >> (c * 5)) % 97) / 96.0f - (c == 2 ? 0.2f : 0.0f));
        }
    return v;
}

}  // namespace

TEST_F(GpuTextureStatsTest, SpecialValuesAreCountedAsTheCpuCountsThem) {
    std::vector<float> v = pattern(13, 7, 3.0f);
    // One texel each: NaN in red, +Inf in green, -Inf in blue, a negative, NaN and Inf together
    // (counted once, as NaN), and -0.0 (not negative).
    auto at = [&](int x, int y, int c) -> float& { return v[std::size_t((y * 13 + x) * 4 + c)]; };
    at(0, 0, 0) = kNan;
    at(5, 3, 1) = kInf;
    at(12, 6, 2) = -kInf;
    at(7, 2, 0) = -4.5f;
    at(3, 5, 0) = kNan;
    at(3, 5, 1) = kInf;
    at(9, 1, 3) = -0.0f;
    gl::Texture t = upload(TextureFormat::RGBA32F, 13, 7, v);
    expectSame(t, {13, 7, TextureFormat::RGBA32F, 1}, 0);
    std::optional<TextureAnalysis> a =
        stats.analyse(t.name(), {13, 7, TextureFormat::RGBA32F, 1}, 0, false, 0.1f, 50.0f);
    ASSERT_TRUE(a);
    EXPECT_EQ(a->nanTexels, 2);
    EXPECT_EQ(a->infTexels, 2);
    EXPECT_GE(a->negativeTexels, 1);
}

TEST_F(GpuTextureStatsTest, HdrTailGetsTheSameLogarithmicHistogram) {
    std::vector<float> v = pattern(40, 24, 0.8f);
    v[4 * 100] = 3000.0f;  // one sun texel: the tail that makes the bins logarithmic
    v[4 * 101 + 1] = 250.0f;
    for (float& x : v) x = std::abs(x);  // no negatives: a log histogram
    gl::Texture t = upload(TextureFormat::RGBA16F, 40, 24, v);
    TextureAnalysis cpu =
        analyseImage(gl::readTexture(t.name(), {40, 24, TextureFormat::RGBA16F, 1}, 0), false, 0, 1);
    EXPECT_TRUE(cpu.histogram.logarithmic)
        << "the picture must have an HDR tail for this test: " << cpu.stats[0].min << " " << cpu.stats[1].min
        << " " << cpu.stats[2].min << " " << cpu.stats[3].min;
    expectSame(t, {40, 24, TextureFormat::RGBA16F, 1}, 0);
}

TEST_F(GpuTextureStatsTest, EightBitAndMipLevelsAndLargerThanOneStride) {
    gl::Texture small = upload(TextureFormat::RGBA8, 13, 7, pattern(13, 7, 1.0f));
    expectSame(small, {13, 7, TextureFormat::RGBA8, 1}, 0);
    // 300x24: more texels than the 16x16 workgroups of 16x16 threads cover in one stride.
    gl::Texture big = upload(TextureFormat::RGBA16F, 300, 24, pattern(300, 24, 5.0f), 3);
    expectSame(big, {300, 24, TextureFormat::RGBA16F, 3}, 0);
    expectSame(big, {300, 24, TextureFormat::RGBA16F, 3}, 2);
}

TEST_F(GpuTextureStatsTest, DepthShownAsDistanceWithTheSkyApart) {
    const int w = 17, h = 9;
    std::vector<float> depth;
    for (int i = 0; i < w * h; ++i) depth.push_back(i % 5 == 0 ? 1.0f : float(i) / float(w * h));
    gl::Texture t = gl::Texture::create2D(TextureFormat::Depth32F, w, h, 1, "test.depth");
    glTextureSubImage2D(t.name(), 0, 0, 0, w, h, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
    expectSame(t, {w, h, TextureFormat::Depth32F, 1}, 0, true);
    expectSame(t, {w, h, TextureFormat::Depth32F, 1}, 0, false);
}

TEST_F(GpuTextureStatsTest, SrgbIsLeftToTheReadBack) {
    EXPECT_FALSE(GpuTextureStats::handles({4, 4, TextureFormat::SRGB8_ALPHA8, 1}));
    EXPECT_TRUE(GpuTextureStats::handles({4, 4, TextureFormat::RGBA16F, 1}));
}

// The inspector's analyser: on a software renderer it reads back (the compute pass is slower there),
// and asked to count on the GPU it gives the read-back's numbers.
TEST_F(GpuTextureStatsTest, AnalyserCountsOnTheGpuOnlyWhereThatPays) {
    std::vector<float> v = pattern(13, 7, 2.0f);
    v[0] = kNan;
    gl::Texture t = upload(TextureFormat::RGBA16F, 13, 7, v);
    TextureSource source{t.name(), {13, 7, TextureFormat::RGBA16F, 1}, "test.stats"};
    ViewSettings settings;
    TextureAnalyser automatic, gpu(0.5, true);
    ASSERT_TRUE(automatic.update(source, settings, 0.0));
    ASSERT_TRUE(gpu.update(source, settings, 0.0));
    EXPECT_TRUE(gpu.countsOnGpu());
    const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    EXPECT_EQ(automatic.countsOnGpu(), !isSoftwareRenderer(renderer ? renderer : ""));
    EXPECT_EQ(gpu.analysis().nanTexels, 1);
    EXPECT_EQ(gpu.analysis().nanTexels, automatic.analysis().nanTexels);
    EXPECT_EQ(gpu.analysis().stats[1].max, automatic.analysis().stats[1].max);
    EXPECT_EQ(gpu.analysis().histogram.counts[2], automatic.analysis().histogram.counts[2]);
}
