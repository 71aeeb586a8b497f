#include "ui/pixel_probe.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include <imgui.h>

#include "base/log.hpp"
#include "base/words.hpp"
#include "gl/gl_formats.hpp"
#include "ui/texture_analysis.hpp"
#include "ui/ui_style.hpp"

namespace fx {

ProbeSample probeTexel(const TextureSource& source, int level, int x, int y) {
    ProbeSample s;
    s.level = level;
    s.x = x;
    s.y = y;
    s.size = source.levelSize(level);
    if (!source.alive() || level < 0 || level >= source.levels()) return s;
    if (x < 0 || y < 0 || x >= s.size.width || y >= s.size.height) return s;
    s.texel = gl::readTexel(source.native, source.spec, level, x, y);
    s.channels = readbackChannelCount(source.spec.format);
    return s;
}

std::vector<ProbeSample> probeChain(const TextureChain& chain, const SourceLookup& lookup, int x, int y,
                                    Size2D from) {
    std::vector<ProbeSample> samples;
    for (const ChainMember& m : chain.members) {
        int mx = mapTexelCoordinate(x, from.width, m.size.width);
        int my = mapTexelCoordinate(y, from.height, m.size.height);
        ProbeSample s = probeTexel(lookup(m.texture), m.level, mx, my);
        s.label = m.label;
        s.size = m.size;
        samples.push_back(std::move(s));
    }
    return samples;
}

std::string exactFloatText(float value) {
    if (std::isnan(value)) return std::signbit(value) ? "-nan" : "nan";
    if (std::isinf(value)) return value < 0 ? "-inf" : "inf";
    // The shortest digits that read back as the same float, written out in full where a reader takes
    // them in at a glance (300, 270.5, 0.001), in exponent form only far from 1 (1e-05, 6.5e+09).
    char text[64];
    const float magnitude = std::fabs(value);
    const bool plain = magnitude == 0.0f || (magnitude >= 1e-4f && magnitude < 1e7f);
    auto [end, ec] = std::to_chars(text, text + sizeof text - 1, value,
                                   plain ? std::chars_format::fixed : std::chars_format::scientific);
    if (ec != std::errc()) return "?";
    *end = '\0';
    return text;
}

std::string storedValueText(float value, TextureFormat format) {
    std::string text = exactFloatText(value);
    // An sRGB texel reads back decoded, so it is no longer a whole number of 255ths.
    if (isUnorm8(format) && !isSrgb(format) && std::isfinite(value)) {
        text += cat(" (", static_cast<int>(std::lround(value * 255.0f)), "/255)");
    }
    return text;
}

void PixelProbe::draw(const ProbeSample& sample, const TextureSource& source, bool linearDepth,
                      float cameraNear, float cameraFar, bool pinned) {
    if (sample.channels == 0) {
        ImGui::TextDisabled("%s", say("probe.hover").c_str());
        return;
    }
    ImGui::TextUnformatted(say(pinned ? "probe.texelPinned" : "probe.texel",
                               {{"x", cat(sample.x)},
                                {"y", cat(sample.y)},
                                {"level", cat(sample.level)},
                                {"size", cat(sample.size.width, "x", sample.size.height)}})
                               .c_str());
    static const char* names[4] = {"R", "G", "B", "A"};
    const bool depth = isDepth(source.spec.format);
    for (int c = 0; c < sample.channels; ++c) {
        if (c > 0) ImGui::SameLine(0.0f, 14.0f);
        ImGui::TextColored(depth ? ui_style::kMuted : ui_style::channelColour(c), "%s",
                           depth ? say("probe.depth").c_str() : names[c]);
        ImGui::SameLine();
        float v = sample.texel.value[c];
        ImGui::TextUnformatted(storedValueText(v, source.spec.format).c_str());
    }
    if (depth && linearDepth && std::isfinite(sample.texel.value[0])) {
        ImGui::SameLine(0.0f, 14.0f);
        ImGui::TextDisabled(
            "= %s from the camera (near %g, far %g)",
            exactFloatText(linearizeDepth(sample.texel.value[0], cameraNear, cameraFar)).c_str(),
            double(cameraNear), double(cameraFar));
    }
}

}  // namespace fx
