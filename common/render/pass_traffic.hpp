#pragma once
// What a pass would cost a GPU, modelled rather than timed: GPUs spend post-processing time on memory
// traffic, which a software renderer's timings do not show (llvmpipe's follow the texture-read count,
// docs/bench.md). The model is the one of the reference note on effects (its "How the numbers were
// made"): every texture a pass samples is read once from memory at its size and format (texture caches
// absorb the overlap of neighbouring taps, however many there are), every texture it writes is written
// once, and a texture it adds into (Pass::modify: blending, read-modify-write) is read and written. No
// render-target compression, no cache kept between passes: an upper bound for comparing algorithms, not
// a prediction of one GPU. Mip level 0 of each texture counts; buffers (particles, lights, tiles) are
// not in the frame graph and are not counted.
//
// The graph models every frame at kTrafficModelSize, whatever the frame's own size: a texture declared
// at an output fraction is taken at that fraction of 1920x1080 (textures of fixed size keep theirs), so
// the figures compare with published ones and read the same on every machine and window. The passes are
// the ones this frame declares (a bloom chain declares fewer levels at a tiny size).
//
// Taps (Pass::setTaps) are texture lookups per pixel the pass writes; over the frame they add up to
// taps per output pixel, weighted by each pass's share of the output's pixels.
#include <cstddef>
#include <cstdint>
#include <string>

#include "base/size2d.hpp"
#include "base/texture_spec.hpp"

namespace fx {

inline constexpr Size2D kTrafficModelSize{1920, 1080};

struct PassTraffic {
    std::uint64_t readBytes = 0;     // sampled or added into: once per texture, level 0
    std::uint64_t writtenBytes = 0;  // every texture it writes, level 0
    std::uint64_t pixels = 0;        // the largest texture it writes, in texels: what its taps are per
    std::uint64_t total() const { return readBytes + writtenBytes; }
    // Adds the bytes (a frame's total); pixels stay: they belong to one pass.
    PassTraffic& operator+=(const PassTraffic& other);
};

// Level 0 of `spec`: width x height x bytes per texel.
std::uint64_t levelZeroBytes(const TextureSpec& spec);

// One texture of one pass, at the model's size, for modelTraffic.
struct ModelledAccess {
    TextureSpec spec;
    bool reads = false;
    bool writes = false;
};

PassTraffic modelTraffic(const ModelledAccess* accesses, std::size_t count);

// A pass's taps over the whole output: taps x the pixels it writes / the output's pixels.
double tapsPerOutputPixel(double taps, const PassTraffic& traffic, Size2D output = kTrafficModelSize);

// "40.3 MB": bytes in decimal megabytes (10^6, as published figures give them), one decimal.
std::string megabytesText(std::uint64_t bytes);

}  // namespace fx
