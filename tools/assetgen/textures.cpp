#include "textures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <vector>

#include "hash_noise.hpp"

namespace fx::assetgen {
namespace {

std::uint8_t toByte(float v) {
    float c = std::clamp(v, 0.0f, 1.0f);
    return static_cast<std::uint8_t>(c * 255.0f + 0.5f);
}

float smoothstep(float edge0, float edge1, float x) {
    float t = std::clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

void setRgb(ByteImage& image, int x, int y, float r, float g, float b) {
    image.texel(x, y, 0) = toByte(r);
    image.texel(x, y, 1) = toByte(g);
    image.texel(x, y, 2) = toByte(b);
}

// Distance (in texels) from the nearest multiple of `cell`, for lines along a grid.
float distanceToGrid(int coordinate, int cell) {
    int m = coordinate % cell;
    return static_cast<float>(std::min(m, cell - 1 - m));
}

}  // namespace

const Quantile kCloudQuantiles[8] = {{0.0f, 0.0f},   {0.05f, 0.12f}, {0.25f, 0.33f},  {0.5f, 0.47f},
                                     {0.75f, 0.58f}, {0.95f, 0.71f}, {0.995f, 0.82f}, {1.0f, 0.90f}};

ByteImage groundChecker() {
    constexpr int kSize = 256, kCell = 32;
    ByteImage image = makeByteImage(kSize, kSize, 3);
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            int cx = x / kCell, cy = y / kCell;
            bool light = ((cx + cy) & 1) == 0;
            // Each check gets its own slight brightness, like worn tiles.
            float variation = 0.06f * (unitFloat(hash2(cx, cy, 0x67a1u)) - 0.5f);
            float base = (light ? 0.78f : 0.42f) + variation;
            float grout = std::min(distanceToGrid(x, kCell), distanceToGrid(y, kCell));
            float shade = base * (0.8f + 0.2f * smoothstep(0.0f, 1.5f, grout));
            setRgb(image, x, y, shade * 1.0f, shade * 0.96f, shade * 0.88f);
        }
    }
    return image;
}

ByteImage cloudDensity() {
    constexpr int kSize = 512;
    constexpr int kBasePeriod = 8;  // cells per tile: a 64-texel base wavelength
    constexpr int kOctaves = 5;
    constexpr float kGain = 0.5f;
    const std::size_t count = static_cast<std::size_t>(kSize) * kSize;
    std::vector<float> raw(count);
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            float u = (static_cast<float>(x) + 0.5f) * (static_cast<float>(kBasePeriod) / kSize);
            float v = (static_cast<float>(y) + 0.5f) * (static_cast<float>(kBasePeriod) / kSize);
            raw[static_cast<std::size_t>(y) * kSize + static_cast<std::size_t>(x)] =
                tileableFbm(u, v, kBasePeriod, kOctaves, kGain, 0xc10d5u);
        }
    }
    // Shape the histogram: the texel of rank r gets the value the quantile table gives at (r + 0.5)/N.
    // Ties are broken by position, so the order (and the file) never depends on the sort algorithm.
    std::vector<std::uint32_t> order(count);
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        return raw[a] < raw[b] || (raw[a] == raw[b] && a < b);
    });
    ByteImage image = makeByteImage(kSize, kSize, 1);
    std::size_t knot = 1;
    for (std::size_t rank = 0; rank < count; ++rank) {
        float q = (static_cast<float>(rank) + 0.5f) / static_cast<float>(count);
        while (knot + 1 < std::size(kCloudQuantiles) && q > kCloudQuantiles[knot].fraction) ++knot;
        const Quantile& a = kCloudQuantiles[knot - 1];
        const Quantile& b = kCloudQuantiles[knot];
        float t = (q - a.fraction) / (b.fraction - a.fraction);
        image.texels[order[rank]] = toByte(a.value + (b.value - a.value) * t);
    }
    return image;
}

ByteImage fireSprite() {
    constexpr int kSize = 256;
    constexpr float kBaseV = 0.27f;   // centre of the round base
    constexpr float kRadius = 0.22f;  // half-width of the base
    constexpr float kTipV = 0.95f;
    ByteImage image = makeByteImage(kSize, kSize, 4);
    for (int y = 0; y < kSize; ++y) {
        float v = (static_cast<float>(y) + 0.5f) / kSize;
        // Half-width of the flame at this height: a circle below the base centre, a taper above it.
        float halfWidth = 0.0f;
        if (v <= kBaseV) {
            float dy = v - kBaseV;
            float r2 = kRadius * kRadius - dy * dy;
            halfWidth = r2 > 0.0f ? std::sqrt(r2) : 0.0f;
        } else if (v < kTipV) {
            float t = (v - kBaseV) / (kTipV - kBaseV);
            // Full width at the base, a rounded shoulder, then a sharp tip.
            halfWidth = kRadius * (1.0f - t * t) * (1.0f - 0.35f * t);
        }
        // Low-frequency wobble of the outline, so the flame is not a perfect lathe shape.
        float wobble = 0.9f + 0.2f * valueNoise1D(v * 6.0f, 0xf17eu);
        halfWidth *= wobble;
        float centre = 0.5f + 0.03f * (valueNoise1D(v * 3.0f, 0xce7eu) - 0.5f) * smoothstep(kBaseV, kTipV, v);
        for (int x = 0; x < kSize; ++x) {
            float u = (static_cast<float>(x) + 0.5f) / kSize;
            float alpha = 0.0f;
            if (halfWidth > 1e-4f) {
                float d = std::abs(u - centre) / halfWidth;  // 0 on the axis, 1 on the outline
                alpha = 1.0f - smoothstep(0.85f, 1.0f, d);
            }
            // Warm white that turns yellow toward the edge; only the alpha matters to the lesson.
            float edge = halfWidth > 1e-4f ? std::clamp(std::abs(u - centre) / halfWidth, 0.0f, 1.0f) : 1.0f;
            image.texel(x, y, 0) = 255;
            image.texel(x, y, 1) = toByte(0.95f - 0.2f * edge);
            image.texel(x, y, 2) = toByte(0.75f - 0.45f * edge);
            image.texel(x, y, 3) = toByte(alpha);
        }
    }
    return image;
}

ByteImage cratePlanks() {
    constexpr int kSize = 256, kFrame = 24, kPlank = 52;
    ByteImage image = makeByteImage(kSize, kSize, 3);
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            int edge = std::min(std::min(x, kSize - 1 - x), std::min(y, kSize - 1 - y));
            bool frame = edge < kFrame;
            // Grain: stretched noise along the plank direction.
            float grain =
                tileableGradientNoise(static_cast<float>(x) / 64.0f, static_cast<float>(y) / 6.0f, 4, 0x6a1u);
            float shade;
            if (frame) {
                shade = 0.58f + 0.06f * grain;
                if (edge < 2 || edge >= kFrame - 2) shade *= 0.6f;  // dark gap around the frame
            } else {
                int plank = (y - kFrame) / kPlank;
                float gap = distanceToGrid(y - kFrame, kPlank);
                shade = 0.66f + 0.08f * (unitFloat(hash2(plank, 0, 0x91a4u)) - 0.5f) + 0.07f * grain;
                shade *= 0.55f + 0.45f * smoothstep(0.0f, 2.0f, gap);
            }
            setRgb(image, x, y, shade * 1.0f, shade * 0.74f, shade * 0.47f);
        }
    }
    return image;
}

ByteImage suitFabric() {
    constexpr int kSize = 256, kThread = 8;
    ByteImage image = makeByteImage(kSize, kSize, 3);
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            // A plain weave: threads over and under in a checker of kThread-texel cells.
            bool over = (((x / kThread) + (y / kThread)) & 1) == 0;
            int along = over ? x % kThread : y % kThread;
            float t = (static_cast<float>(along) + 0.5f) / kThread;
            float bulge = 4.0f * t * (1.0f - t);  // bright in the middle of a thread, darker at its ends
            float shade = 0.8f + 0.2f * bulge;
            setRgb(image, x, y, shade, shade, shade);
        }
    }
    return image;
}

ByteImage cutoutLattice() {
    constexpr int kSize = 128;
    constexpr int kCell = 64;  // 2 cells across: holes big enough to see in a shadow on the ground
    constexpr int kBar = 16;   // bar width; the hole is the rest of the cell
    ByteImage image = makeByteImage(kSize, kSize, 4);
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            // Bars sit on the cell borders (half a bar each side), so the pattern tiles.
            int cx = (x + kBar / 2) % kCell, cy = (y + kBar / 2) % kCell;
            bool bar = cx < kBar || cy < kBar;
            image.texel(x, y, 0) = 214;
            image.texel(x, y, 1) = 188;
            image.texel(x, y, 2) = 140;
            image.texel(x, y, 3) = bar ? 255 : 0;
        }
    }
    return image;
}

}  // namespace fx::assetgen
