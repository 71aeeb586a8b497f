#include "effects/clouds/cloud_temporal.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>

#include "effects/clouds/clouds_bindings.hpp"

namespace fx {
namespace {

struct AccumulateUniforms {
    glm::mat4 inverseProjection{1.0f};
    glm::mat3 rotation{1.0f};
    glm::mat4 previousFromCamera{1.0f};
    glm::vec2 slabMiddleAndEyeY{0.0f};
    float weight = 1.0f;
    int depthStride = 1;
};

}  // namespace

std::uint64_t CloudTemporal::historyBytes() const {
    std::uint64_t total = 0;
    for (const gl::Texture& t : history_)
        if (t) total += textureBytes(t.spec());
    return total;
}

void CloudTemporal::declare(FrameGraph& graph, const CloudPass& march, const CloudInputs& inputs,
                            const CloudDensityTexture& density, const CloudFrameSettings& settings,
                            const CloudTemporalOptions& options, std::uint64_t settingsKey,
                            Size2D outputSize) {
    const int divisor = options.halfResolution ? 2 : 1;
    const bool accumulating = options.accumulate && !outputSize.empty();
    // What the composite lays over the scene is always "clouds.result" (the bench compares it): the
    // march's own output without accumulation, the average with it.
    TextureHandle layer = march.declareLayer(graph, inputs, density, settings, divisor,
                                             accumulating ? "clouds.layer" : "clouds.result");
    TextureHandle result = layer;

    if (!options.accumulate) {
        // No history kept: its memory goes back, and the next average starts afresh.
        history_[0] = gl::Texture();
        history_[1] = gl::Texture();
        historySize_ = {};
        frames_ = 0;
    } else if (!outputSize.empty()) {
        Size2D size{std::max(outputSize.width / divisor, 1), std::max(outputSize.height / divisor, 1)};
        if (size.width != historySize_.width || size.height != historySize_.height || !history_[0]) {
            for (int i = 0; i < 2; ++i)
                history_[i] = gl::Texture::create2D(TextureFormat::RGBA16F, size.width, size.height, 1,
                                                    i == 0 ? "clouds.history[0]" : "clouds.history[1]");
            historySize_ = size;
            frames_ = 0;
        }
        if (settingsKey != key_) frames_ = 0;
        key_ = settingsKey;

        const gl::Texture& previous = history_[newest_];
        const gl::Texture& next = history_[1 - newest_];
        const TextureSize historySize = TextureSize::outputFraction(1, divisor);  // for the traffic model
        TextureHandle before =
            graph.importTexture("clouds.history.previous", previous.spec(), previous.name(), historySize);
        TextureHandle after =
            graph.importTexture("clouds.history.next", next.spec(), next.name(), historySize);

        AccumulateUniforms u;
        u.inverseProjection = glm::inverse(settings.projection);
        u.rotation = glm::transpose(glm::mat3(settings.view));
        u.previousFromCamera =
            (frames_ == 0 ? settings.projection * settings.view : previousViewProjection_) *
            glm::translate(glm::mat4(1.0f), settings.cameraPosition);
        u.slabMiddleAndEyeY = {0.5f * (settings.march.bottom + settings.march.top),
                               settings.cameraPosition.y};
        u.weight = frames_ == 0
                       ? 1.0f
                       : std::max(1.0f / float(frames_ + 1), 1.0f / float(std::max(options.maxFrames, 1)));
        u.depthStride = divisor;
        const bool depth = (settings.features & cloudDepthAware) != 0;
        TextureHandle depthTexture = inputs.depth;
        const FullscreenPass* program = &accumulate_;
        Pass& pass = accumulate_.addPass(
            graph, "clouds accumulate", [program, u, layer, before, depth, depthTexture](PassContext& ctx) {
                GLuint prog = program->program();
                glProgramUniformMatrix4fv(prog, glsl::kAccumulateInverseProjectionLocation, 1, GL_FALSE,
                                          glm::value_ptr(u.inverseProjection));
                glProgramUniformMatrix3fv(prog, glsl::kAccumulateViewToWorldRotationLocation, 1, GL_FALSE,
                                          glm::value_ptr(u.rotation));
                glProgramUniformMatrix4fv(prog, glsl::kAccumulatePreviousFromCameraLocation, 1, GL_FALSE,
                                          glm::value_ptr(u.previousFromCamera));
                glProgramUniform2fv(prog, glsl::kAccumulateSlabMiddleAndEyeYLocation, 1,
                                    glm::value_ptr(u.slabMiddleAndEyeY));
                glProgramUniform1f(prog, glsl::kAccumulateCurrentWeightLocation, u.weight);
                Size2D target = ctx.targetSize();
                glProgramUniform2f(prog, glsl::kAccumulateTargetSizeLocation,
                                   float(std::max(target.width, 1)), float(std::max(target.height, 1)));
                glProgramUniform1i(prog, glsl::kAccumulateDepthStrideLocation, u.depthStride);
                program->draw({ctx.native(layer), ctx.native(before), depth ? ctx.native(depthTexture) : 0});
            });
        result =
            pass.create("clouds.result", {TextureSize::outputFraction(1, divisor), TextureFormat::RGBA16F},
                        TextureUsage::ColorAttachment);   // attachment 0
        pass.read(layer).read(before).writeColor(after);  // attachment 1
        // This frame's texel and its 3x3 neighbourhood (the clamp), the history where it was, the depth.
        pass.setTaps(depth ? 12 : 11);
        if (depth) pass.read(inputs.depth);

        previousViewProjection_ = settings.projection * settings.view;
        newest_ = 1 - newest_;
        ++frames_;
    }

    const FullscreenPass* composite = &composite_;
    PassState over = FullscreenPass::state();
    over.blend = true;
    over.blendFunction = BlendFunction::premultipliedAlpha();
    composite_
        .addPass(graph, "clouds composite",
                 [composite, result](PassContext& ctx) { composite->draw({ctx.native(result)}); })
        .read(result)
        .modify(inputs.color, TextureUsage::ColorAttachment)
        .setState(over)
        .setTaps(1);
}

}  // namespace fx
