// Bloom (lesson 06): the weights of every kernel, pinned with impulse inputs at exact 2:1 and 4:1
// ratios. The grey invariants only show that the weights sum to 1; a kernel with the right sum and the
// wrong shape passes them. The numbers are the chapters': Shader effects §3.7.1-3.7.3 and its test
// table, Bloom §1.5 and §1.6 (the derived 1/64 binomial and the x192 upsample matrix).
#include <algorithm>
#include <cmath>
#include <functional>
#include <map>

#include "gl_test.hpp"
#include "test_bloom_harness.hpp"

using namespace fx;
using namespace fx::test;

namespace {

class BloomKernels : public GlTest {
protected:
    void SetUp() override {
        GlTest::SetUp();
        ASSERT_TRUE(programsBuilt());
    }
    BloomEffects effects;
};

// An image of `width` x `height`, black with alpha 1, holding `value` at each texel of `at`.
FloatImage impulses(int width, int height, const std::vector<std::pair<int, int>>& at, float value) {
    return makeImage(width, height, [&](int x, int y) {
        bool hit = std::find(at.begin(), at.end(), std::make_pair(x, y)) != at.end();
        return std::array<float, 4>{hit ? value : 0.0f, hit ? value : 0.0f, hit ? value : 0.0f, 1.0f};
    });
}

// The weight a 2:1 downsample gives source texel (2X + dx, 2Y + dy) in destination texel (X, Y): the
// 4x4 block dx, dy in [-1, 2] around the destination's own 2x2.
using DownKernel = std::function<double(int dx, int dy)>;

// The destination a 2:1 downsample with `kernel` makes of `source`, computed on the CPU.
FloatImage downsampleOnCpu(const FloatImage& source, const DownKernel& kernel) {
    FloatImage out = makeFloatImage(source.width / 2, source.height / 2, 4);
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x)
            for (int dy = -1; dy <= 2; ++dy)
                for (int dx = -1; dx <= 2; ++dx) {
                    int sx = std::clamp(2 * x + dx, 0, source.width - 1);
                    int sy = std::clamp(2 * y + dy, 0, source.height - 1);
                    out.texel(x, y, 0) += float(kernel(dx, dy) * source.texel(sx, sy, 0));
                }
    return out;
}

// The largest difference in the red channel; images of different sizes differ by infinity.
float worstDifference(const FloatImage& a, const FloatImage& b) {
    if (a.width != b.width || a.height != b.height) return INFINITY;
    float worst = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x)
            worst = std::max(worst, std::abs(a.texel(x, y, 0) - b.texel(x, y, 0)));
    return worst;
}

// Shader effects §3.7.2 at exactly 2x: the centre tap reads the inner 2x2 four times, each diagonal
// tap one 2x2 quad of the 4x4 block: inner texels 4/32 + 1/32 = 5/32, the 12 outer ones 1/32.
double shaderEffectsDownWeight(int dx, int dy) {
    bool inner = (dx == 0 || dx == 1) && (dy == 0 || dy == 1);
    return inner ? 5.0 / 32.0 : 1.0 / 32.0;
}

// Bloom §1.5-1.6 at exactly 2x: four diagonal taps at +-0.75 texel make ([1 3 3 1] / 8) x ([1 3 3 1] / 8).
double binomialWeight(int dx, int dy) {
    const double b[4] = {1.0 / 8, 3.0 / 8, 3.0 / 8, 1.0 / 8};
    return b[dx + 1] * b[dy + 1];
}

// One destination texel's footprint in the smaller source: source texel (relative) -> weight.
using Footprint = std::map<std::pair<int, int>, double>;

// Upsampling at exactly 2x, destination texel D = 2c + phase reads source texel c + r with weight
// w_phase(r), so one impulse of `value` at source texel s shows w_phase(r) in destination 2(s - r) +
// phase: every phase's footprint from one run. Offsets r within +-4 texels are looked at.
Footprint footprintOfPhase(const FloatImage& out, std::pair<int, int> s, std::pair<int, int> phase,
                           float value) {
    Footprint f;
    for (int ry = -4; ry <= 4; ++ry)
        for (int rx = -4; rx <= 4; ++rx) {
            float v = out.texel(2 * (s.first - rx) + phase.first, 2 * (s.second - ry) + phase.second, 0);
            if (v != 0.0f) f[{rx, ry}] = double(v) / value;
        }
    return f;
}

// The Shader effects upsample (§3.7.3) computed from its formula on the CPU: taps at the destination
// centre (x3), the 4 diagonals at +-1 source texel (x2) and the 4 axial at +-2 (x1), / 15, each tap
// a bilinear fetch. Source texel c + r has its centre at r + 0.5; destination `phase` sits at c +
// 0.25 + 0.5 phase.
Footprint shaderEffectsUpsampleOnCpu(std::pair<int, int> phase) {
    struct Tap {
        double x, y, weight;
    };
    const Tap taps[] = {{0, 0, 3},  {-1, 1, 2}, {1, 1, 2},  {1, -1, 2}, {-1, -1, 2},
                        {-2, 0, 1}, {2, 0, 1},  {0, -2, 1}, {0, 2, 1}};
    Footprint f;
    for (const Tap& t : taps) {
        double x = 0.25 + 0.5 * phase.first + t.x - 0.5, y = 0.25 + 0.5 * phase.second + t.y - 0.5;
        int x0 = int(std::floor(x)), y0 = int(std::floor(y));
        double fx = x - x0, fy = y - y0;
        f[{x0, y0}] += t.weight / 15 * (1 - fx) * (1 - fy);
        f[{x0 + 1, y0}] += t.weight / 15 * fx * (1 - fy);
        f[{x0, y0 + 1}] += t.weight / 15 * (1 - fx) * fy;
        f[{x0 + 1, y0 + 1}] += t.weight / 15 * fx * fy;
    }
    std::erase_if(f, [](const auto& entry) { return entry.second == 0.0; });
    return f;
}

// The composite's upsample (the chain's upsample shader) of a glow holding one impulse of `value` at
// `s`, onto a black scene twice its size: scene + 1 x Up(glow) is Up(glow) alone.
FloatImage upsampleImpulse(const BloomEffects& fx, BloomFilters filters, float upOffset, int glowSize,
                           std::pair<int, int> s, float value, std::string& errors) {
    gl::Texture glowTexture =
        gl::Texture::create2D(TextureFormat::RGBA32F, glowSize, glowSize, 1, "test.glow");
    FloatImage glowImage = impulses(glowSize, glowSize, {s}, value);
    glTextureSubImage2D(glowTexture.name(), 0, 0, 0, glowSize, glowSize, GL_RGBA, GL_FLOAT,
                        glowImage.texels.data());
    EffectRunner runner(2 * glowSize, 2 * glowSize);
    FloatImage out =
        runner.run(impulses(2 * glowSize, 2 * glowSize, {}, 0.0f), TextureFormat::RGBA32F,
                   [&](FrameGraph& g, TextureHandle scene) {
                       TextureHandle glow = g.importTexture(
                           "test.glow", {glowSize, glowSize, TextureFormat::RGBA32F, 1}, glowTexture.name());
                       return fx.composite.declare(g, scene, glow, {filters, upOffset, 1.0f}).output;
                   });
    errors = runner.lastError;
    return out;
}

}  // namespace

TEST_F(BloomKernels, ShaderEffectsHighPassAtFourToOneWeighsSixteenTexelsByOneSixteenthEach) {
    // Threshold 0 and intensity 1 make the bright pass a plain average. Each of the 16 places inside a
    // 4x4 block gets an impulse of 16 in a block of its own (blocks 3 apart): the block's level-0 texel
    // reads exactly 1 for every place, and no neighbouring block sees any of it.
    const int w = 64, h = 64;
    std::vector<std::pair<int, int>> at, blocks;
    for (int py = 0; py < 4; ++py)
        for (int px = 0; px < 4; ++px) {
            blocks.push_back({1 + 3 * px, 1 + 3 * py});
            at.push_back({4 * blocks.back().first + px, 4 * blocks.back().second + py});
        }
    BloomChainSettings s = shaderEffectsChain(0.0f, 1.0f, 1);
    s.format = TextureFormat::RGBA32F;
    EffectRunner runner(w, h);
    FloatImage level0 = runChain(runner, effects, impulses(w, h, at, 16.0f), TextureFormat::RGBA32F, s,
                                 [](const BloomChain::Declared& d) { return d.down[0]; });
    ASSERT_EQ(level0.width, 16) << runner.lastError;
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) {
            bool hit = std::find(blocks.begin(), blocks.end(), std::make_pair(x, y)) != blocks.end();
            EXPECT_EQ(level0.texel(x, y, 0), hit ? 1.0f : 0.0f) << "level-0 texel (" << x << ", " << y << ")";
        }
}

TEST_F(BloomKernels, ShaderEffectsDownsampleAtTwoToOneWeighsInnerFiveThirtySecondsOuterOne) {
    // An impulse of 16 x 32 in the scene is an impulse of 32 in level 0 (the block average above); level
    // 1 then shows the kernel. Four runs put the impulse at the four parities of a level-0 texel, so
    // every one of the 16 weights is seen.
    BloomChainSettings s = shaderEffectsChain(0.0f, 1.0f, 2);
    s.format = TextureFormat::RGBA32F;
    EffectRunner runner(64, 64);
    for (auto [lx, ly] : {std::pair{8, 8}, std::pair{9, 8}, std::pair{8, 9}, std::pair{9, 9}}) {
        FloatImage scene = impulses(64, 64, {{4 * lx + 1, 4 * ly + 2}}, 16.0f * 32.0f);
        FloatImage level0 = runChain(runner, effects, scene, TextureFormat::RGBA32F, s,
                                     [](const BloomChain::Declared& d) { return d.down[0]; });
        FloatImage level1 = runChain(runner, effects, scene, TextureFormat::RGBA32F, s,
                                     [](const BloomChain::Declared& d) { return d.down[1]; });
        ASSERT_EQ(level1.width, 8) << runner.lastError;
        ASSERT_EQ(worstDifference(level0, impulses(16, 16, {{lx, ly}}, 32.0f)), 0.0f);
        // 32 x 5/32 = 5 in the destination whose 2x2 holds the impulse, 32 x 1/32 = 1 in the three
        // neighbours whose outer ring it is in, and the four add up to 8: 32 spread over 2x2 the area.
        EXPECT_EQ(worstDifference(level1, downsampleOnCpu(level0, shaderEffectsDownWeight)), 0.0f)
            << "impulse at level-0 texel (" << lx << ", " << ly << ")";
        EXPECT_EQ(level1.texel(lx / 2, ly / 2, 0), 5.0f);
    }
}

TEST_F(BloomKernels, BloomChapterBrightPassAndDownsampleAtTwoToOneAreTheOneSixtyFourthBinomial) {
    // The Bloom chapter's bright pass blurs with four taps at +-0.75 texel before the threshold (0
    // here): an impulse of 64 comes out as 9, 3, 3, 1 in the 2x2 level-0 texels around it, oriented by
    // its parity. Its downsample uses the same taps on level 0: level 1 is the binomial of level 0.
    BloomChainSettings s = bloomChapterChain(0.0f, 2);
    s.format = TextureFormat::RGBA32F;
    EffectRunner runner(64, 64);
    for (auto at : {std::pair{32, 32}, std::pair{33, 32}, std::pair{32, 33}, std::pair{33, 33}}) {
        FloatImage scene = impulses(64, 64, {at}, 64.0f);
        FloatImage level0 = runChain(runner, effects, scene, TextureFormat::RGBA32F, s,
                                     [](const BloomChain::Declared& d) { return d.down[0]; });
        FloatImage level1 = runChain(runner, effects, scene, TextureFormat::RGBA32F, s,
                                     [](const BloomChain::Declared& d) { return d.down[1]; });
        ASSERT_EQ(level0.width, 32) << runner.lastError;
        FloatImage input = impulses(64, 64, {at}, 64.0f);
        EXPECT_EQ(worstDifference(level0, downsampleOnCpu(input, binomialWeight)), 0.0f)
            << "impulse at (" << at.first << ", " << at.second << ")";
        EXPECT_EQ(level0.texel(at.first / 2, at.second / 2, 0), 9.0f);
        EXPECT_LE(worstDifference(level1, downsampleOnCpu(level0, binomialWeight)), 1e-5f);
    }
}

TEST_F(BloomKernels, ShaderEffectsUpsampleAtTwoToOneReadsTwentyFourTexelsInASixBySixWindow) {
    // §3.7.3: nine bilinear taps at an exact 2x ratio touch 24 distinct source texels inside a 6x6
    // window, weights summing to 1; for each of the four destination phases the weights are those of
    // the formula (multiples of 1/240, so an impulse of 240 reads back as integers, exact in RGBA16F).
    std::string errors;
    const std::pair<int, int> s{8, 8};
    FloatImage out = upsampleImpulse(effects, BloomFilters::shaderEffects, shaderEffectsChain().upOffset, 16,
                                     s, 240.0f, errors);
    ASSERT_EQ(out.width, 32) << errors;
    for (auto phase : {std::pair{0, 0}, std::pair{1, 0}, std::pair{0, 1}, std::pair{1, 1}}) {
        Footprint f = footprintOfPhase(out, s, phase, 240.0f);
        EXPECT_EQ(f.size(), 24u) << "phase " << phase.first << ", " << phase.second;
        int minX = 99, maxX = -99, minY = 99, maxY = -99;
        double sum = 0;
        for (auto [r, w] : f) {
            minX = std::min(minX, r.first), maxX = std::max(maxX, r.first);
            minY = std::min(minY, r.second), maxY = std::max(maxY, r.second);
            sum += w;
        }
        EXPECT_EQ(maxX - minX + 1, 6);
        EXPECT_EQ(maxY - minY + 1, 6);
        EXPECT_NEAR(sum, 1.0, 1e-6);
        Footprint expected = shaderEffectsUpsampleOnCpu(phase);
        ASSERT_EQ(f.size(), expected.size());
        for (auto [r, w] : expected) {
            EXPECT_NEAR(f[r], w, 1e-6) << "source texel " << r.first << ", " << r.second << " for phase "
                                       << phase.first << ", " << phase.second;
        }
    }
}

TEST_F(BloomKernels, BloomChapterUpsampleAtTwoToOneIsTheChaptersMatrix) {
    // Bloom §1.6, derived: at a destination phase of a quarter texel the upsample weighs the 4x4 source
    // texels around it x 1/192 as below (top row first); the other phases are its mirror images. An
    // impulse of 192 reads back the integers.
    const int matrix[4][4] = {{0, 1, 3, 0}, {1, 24, 34, 9}, {3, 34, 38, 17}, {0, 9, 17, 2}};
    std::string errors;
    const std::pair<int, int> s{8, 8};
    FloatImage out = upsampleImpulse(effects, BloomFilters::bloomChapter, bloomChapterChain().upOffset, 16, s,
                                     192.0f, errors);
    ASSERT_EQ(out.width, 32) << errors;
    std::vector<int> mirrorsSeen;
    for (auto phase : {std::pair{0, 0}, std::pair{1, 0}, std::pair{0, 1}, std::pair{1, 1}}) {
        Footprint f = footprintOfPhase(out, s, phase, 192.0f);
        // The 4x4 window around the phase: source texels c-2..c+1 left of a texel centre, c-1..c+2 right.
        int x0 = phase.first - 2, y0 = phase.second - 2, found = -1;
        double total = 0;
        for (auto [r, w] : f) total += w;
        for (int mirror = 0; mirror < 4 && found < 0; ++mirror) {
            bool same = true;
            for (int row = 0; row < 4; ++row)
                for (int col = 0; col < 4; ++col) {
                    int mx = mirror & 1 ? 3 - col : col, my = mirror & 2 ? 3 - row : row;
                    // Matrix rows run top to bottom, texel rows bottom to top.
                    auto it = f.find({x0 + mx, y0 + 3 - my});
                    double w = it == f.end() ? 0.0 : it->second;
                    same = same && std::abs(w * 192.0 - matrix[row][col]) < 1e-4;
                }
            if (same) found = mirror;
        }
        EXPECT_GE(found, 0) << "phase " << phase.first << ", " << phase.second
                            << " is no mirror of the matrix";
        EXPECT_NEAR(total, 1.0, 1e-6) << "every weight lies in the 4x4 window";
        mirrorsSeen.push_back(found);
    }
    std::sort(mirrorsSeen.begin(), mirrorsSeen.end());
    EXPECT_EQ(mirrorsSeen, (std::vector<int>{0, 1, 2, 3})) << "each phase is a different mirror image";
}
