#include "effects/bloom/bloom_flicker.hpp"

#include <algorithm>
#include <cmath>

#include "effects/bloom/bloom_bindings.hpp"
#include "render/texture_desc.hpp"

namespace fx {

DeclaredPass BloomFlicker::declare(FrameGraph& graph, TextureHandle glow, Size2D size, bool restart) {
    const int mips = fullMipChainLength(size.width, size.height);
    if (size != size_ || !history_[0]) {
        // The new pair is made before the old one goes, so its GL names are new ones: the executor
        // keys its framebuffers by texture names, and a recycled name would find a stale framebuffer.
        std::array<gl::Texture, 2> fresh;
        for (int i = 0; i < 2; ++i) {
            gl::Texture& t = fresh[std::size_t(i)];
            t = gl::Texture::create2D(TextureFormat::RGBA32F, size.width, size.height, mips,
                                      i == 0 ? "bloom.history (a)" : "bloom.history (b)");
            // texelFetch of level 0 only: NEAREST keeps the texture complete before its mips exist.
            glTextureParameteri(t.name(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            glTextureParameteri(t.name(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        }
        history_ = std::move(fresh);
        size_ = size;
        valid_ = false;
    }
    if (restart || !ranLastFrame_) {
        valid_ = false;
        count_ = 0;
        stats_ = {};
    }
    ranLastFrame_ = false;
    const GLuint previous = history_[std::size_t(current_)].name();
    current_ = 1 - current_;
    const GLuint written = history_[std::size_t(current_)].name();
    const TextureSpec spec{size.width, size.height, TextureFormat::RGBA32F, mips};
    TextureHandle prev = graph.importTexture("bloom.history.previous", spec, previous);
    TextureHandle next = graph.importTexture("bloom.history", spec, written);
    TextureHandle out = graph.declareTexture(
        "bloom.flicker", {TextureSize::absolute(size.width, size.height), TextureFormat::RGBA16F, 1});

    const bool hasPrevious = valid_;
    const FullscreenPass* program = &pass_;
    Pass& pass = pass_.addPass(graph, "bloom flicker", [=, this](PassContext& ctx) {
        glProgramUniform1i(program->program(), glsl::kFlickerHasPreviousLocation, hasPrevious ? 1 : 0);
        program->draw({ctx.native(glow), ctx.native(prev)});
        // The glow's energy: the mean of this frame's copy, from its 1x1 mip (one texel read back).
        glGenerateTextureMipmap(written);
        float mean[4] = {};
        glGetTextureImage(written, mips - 1, GL_RGBA, GL_FLOAT, sizeof mean, mean);
        record(0.2126 * mean[0] + 0.7152 * mean[1] + 0.0722 * mean[2], hasPrevious);
        valid_ = true;
        ranLastFrame_ = true;
    });
    pass.read(glow).read(prev).writeColor(out).writeColor(next).setTaps(2);
    return {pass, out};
}

void BloomFlicker::record(double energy, bool hasPrevious) {
    stats_.meanGlow = energy;
    if (hasPrevious) {
        double larger = std::max(energy, lastEnergy_);
        // Both (nearly) black: no glow, no change.
        double change = larger > 1e-9 ? 100.0 * std::abs(energy - lastEnergy_) / larger : 0.0;
        window_[std::size_t(count_ % kWindow)] = change;
        ++count_;
        int n = std::min(count_, kWindow);
        double sum = 0, most = 0;
        for (int i = 0; i < n; ++i) {
            sum += window_[std::size_t(i)];
            most = std::max(most, window_[std::size_t(i)]);
        }
        stats_.measured = true;
        stats_.changePercent = change;
        stats_.meanPercent = sum / n;
        stats_.maxPercent = most;
    }
    lastEnergy_ = energy;
}

}  // namespace fx
