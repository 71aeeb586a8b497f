#include "ui/gpu_texture_stats.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "gl/gl_formats.hpp"

namespace fx {
namespace {

// The totals block of shaders/ui/texture_stats.comp (std430).
struct Totals {
    std::uint32_t minBits[4], maxBits[4], finiteCount[4], nanCount[4], infCount[4], negativeCount[4];
    std::uint32_t texelCounts[4];  // NaN, infinite, negative texels; far-plane texels
    float sum[4];
    std::uint32_t smallestPositive;
    std::uint32_t pad[3];
};
static_assert(sizeof(Totals) == 8 * 16 + 16);

// Uniform locations in shaders/ui/texture_stats.comp.
enum Location : GLint {
    kMode = 0,
    kLevel,
    kChannels,
    kLinearDepth,
    kNear,
    kFar,
    kLow,
    kHigh,
    kLogarithmic,
    kBins,
    kPartialCount
};

constexpr int kGroupsPerAxis = 16;  // at most 16 x 16 workgroups stride over the texture

float fromOrderedBits(std::uint32_t u) {
    u = (u & 0x80000000u) ? u & 0x7fffffffu : ~u;
    float f;
    std::memcpy(&f, &u, sizeof f);
    return f;
}

int groups(int texels) {
    return std::clamp((texels + 15) / 16, 1, kGroupsPerAxis);
}

}  // namespace

GpuTextureStats GpuTextureStats::create() {
    GpuTextureStats s;
    s.program_ = gl::ReloadableProgram({{}, {}, "ui/texture_stats.comp", {}, "inspector statistics"});
    s.totals_ = gl::createBuffer("inspector statistics: totals");
    glNamedBufferStorage(s.totals_.name(), sizeof(Totals), nullptr, GL_DYNAMIC_STORAGE_BIT);
    s.partials_ = gl::createBuffer("inspector statistics: partial sums");
    glNamedBufferStorage(s.partials_.name(), kGroupsPerAxis * kGroupsPerAxis * 4 * sizeof(float), nullptr, 0);
    s.histogram_ = gl::createBuffer("inspector statistics: histogram");
    s.sampler_ = gl::createSampler("inspector statistics (nearest, no compare)");
    // texelFetch ignores filtering; a depth texture set up for shadow comparisons must still give depth.
    glSamplerParameteri(s.sampler_.name(), GL_TEXTURE_COMPARE_MODE, GL_NONE);
    return s;
}

bool GpuTextureStats::handles(const TextureSpec& spec) {
    return spec.format != TextureFormat::SRGB8_ALPHA8 && spec.width > 0 && spec.height > 0;
}

std::optional<TextureAnalysis> GpuTextureStats::analyse(GLuint texture, const TextureSpec& spec, int level,
                                                        bool linearDepth, float cameraNear, float cameraFar,
                                                        int bins) const {
    if (!usable() || texture == 0 || !handles(spec) || level < 0 || level >= spec.mipLevels)
        return std::nullopt;
    const Size2D size = spec.levelSize(level);
    const int channels = std::min(readbackChannelCount(spec.format), 4);
    bins = std::clamp(bins, 1, 256);  // the shader keeps at most 256 bins per channel in shared memory
    const GLuint p = program_.name();

    Totals start{};
    for (int c = 0; c < 4; ++c) {
        start.minBits[c] = 0xffffffffu;  // above every ordered float
        start.maxBits[c] = 0u;
    }
    start.smallestPositive = 0x7f800000u;  // +Inf: no positive value yet
    glNamedBufferSubData(totals_.name(), 0, sizeof start, &start);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, totals_.name());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, partials_.name());
    glBindTextureUnit(0, texture);
    glBindSampler(0, sampler_.name());
    glUseProgram(p);
    glProgramUniform1i(p, kLevel, level);
    glProgramUniform1i(p, kChannels, channels);
    glProgramUniform1i(p, kLinearDepth, linearDepth ? 1 : 0);
    glProgramUniform1f(p, kNear, cameraNear);
    glProgramUniform1f(p, kFar, cameraFar);
    const int gx = groups(size.width), gy = groups(size.height);

    // Pass 1: counts, range, partial sums; pass 2: the sums added up.
    glProgramUniform1i(p, kMode, 0);
    glDispatchCompute(GLuint(gx), GLuint(gy), 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    glProgramUniform1i(p, kMode, 2);
    glProgramUniform1i(p, kPartialCount, gx * gy);
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
    Totals t{};
    glGetNamedBufferSubData(totals_.name(), 0, sizeof t, &t);

    TextureAnalysis a;
    a.level = level;
    a.size = size;
    a.channels = channels;
    a.linearDepth = linearDepth;
    a.nanTexels = t.texelCounts[0];
    a.infTexels = t.texelCounts[1];
    a.negativeTexels = t.texelCounts[2];
    a.farPlaneTexels = t.texelCounts[3];
    for (int c = 0; c < channels; ++c) {
        ChannelStats s;
        s.finiteCount = t.finiteCount[c];
        s.nanCount = t.nanCount[c];
        s.infCount = t.infCount[c];
        s.negativeCount = t.negativeCount[c];
        if (s.finiteCount > 0) {
            s.min = fromOrderedBits(t.minBits[c]);
            s.max = fromOrderedBits(t.maxBits[c]);
            s.mean = double(t.sum[c]) / double(s.finiteCount);
        }
        a.stats.push_back(s);
    }
    float smallestPositive;
    std::memcpy(&smallestPositive, &t.smallestPositive, sizeof smallestPositive);

    // Pass 3: the histogram over the range the statistics chose, as analyseImage chooses it.
    a.histogram = histogramRange(a.stats, smallestPositive, linearDepth, channels);
    ValueHistogram& h = a.histogram;
    std::vector<std::uint32_t> counts(std::size_t(channels * bins), 0u);
    glNamedBufferData(histogram_.name(), GLsizeiptr(counts.size() * sizeof(std::uint32_t)), counts.data(),
                      GL_DYNAMIC_READ);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, histogram_.name());
    glProgramUniform1i(p, kMode, 1);
    glProgramUniform1f(p, kLow, h.low);
    glProgramUniform1f(p, kHigh, h.high);
    glProgramUniform1i(p, kLogarithmic, h.logarithmic ? 1 : 0);
    glProgramUniform1i(p, kBins, bins);
    glDispatchCompute(GLuint(gx), GLuint(gy), 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetNamedBufferSubData(histogram_.name(), 0, GLsizeiptr(counts.size() * sizeof(std::uint32_t)),
                            counts.data());
    for (int c = 0; c < channels; ++c) {
        h.counts[std::size_t(c)].assign(counts.begin() + c * bins, counts.begin() + (c + 1) * bins);
        for (std::uint32_t n : h.counts[std::size_t(c)]) h.peak = std::max(h.peak, n);
    }

    // What this changed goes back, so the next pass starts from the state it expects.
    glUseProgram(0);
    glBindSampler(0, 0);
    glBindTextureUnit(0, 0);
    for (GLuint i = 0; i < 3; ++i) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, i, 0);
    return a;
}

}  // namespace fx
