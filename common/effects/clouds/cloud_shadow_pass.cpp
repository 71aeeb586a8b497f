#include "effects/clouds/cloud_shadow_pass.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "effects/clouds/clouds_bindings.hpp"

namespace fx {
namespace {

// The clouds' Beer-Lambert extinction (clouds.frag): a vertical path through 1/8 of the slab takes the
// chapter's 0.3 per unit of density, so the shadow is as dense as the cloud looks.
constexpr float kDensityScale = 0.3f;

}  // namespace

glm::vec3 cloudShadowToLight(const glm::vec3& lightDirection) {
    glm::vec3 toLight = -lightDirection;
    float length = glm::length(toLight);
    if (!std::isfinite(length) || length < 1e-12f) return {0.0f, 1.0f, 0.0f};
    return toLight / length;
}

void CloudShadowPass::setMapUniforms(const CloudFrameSettings& s, const CloudShadowSettings& shadow,
                                     Size2D target) const {
    GLuint prog = map_.program();
    setCloudCameraUniforms(prog, s);
    // No slab (cloud_march.hpp's guards): bottom == top, and the shader returns 1.
    glm::vec4 range =
        s.march.drawn ? s.march.rangeCountStep() : glm::vec4(s.march.bottom, s.march.bottom, 0, 0);
    glProgramUniform4fv(prog, glsl::kCloudsRangeCountStepLocation, 1, glm::value_ptr(range));
    glm::vec2 th = s.march.thresholdPair();
    if (s.march.thresholdClears) th.y = 0.0f;
    glProgramUniform2fv(prog, glsl::kCloudsThresholdPairLocation, 1, glm::value_ptr(th));
    glProgramUniform2fv(prog, glsl::kCloudsScalesLocation, 1, glm::value_ptr(s.scales));
    // cloudShadowToLight turns a travel direction around: hand it the direction the light travels.
    glm::vec3 toLight = cloudShadowToLight(-shadow.toLight);
    glProgramUniform3fv(prog, glsl::kCloudShadowToLightLocation, 1, glm::value_ptr(toLight));
    glProgramUniform1i(prog, glsl::kCloudShadowSamplesLocation,
                       std::clamp(shadow.samples, 0, kCloudMaxSteps));
    float thickness = s.march.top - s.march.bottom;
    float sigma = thickness > 0.0f && std::isfinite(thickness) ? kDensityScale * 8.0f / thickness : 0.0f;
    glProgramUniform1f(prog, glsl::kCloudShadowSigmaPerDensityLocation, sigma);
    glProgramUniform2f(prog, glsl::kCloudsTargetSizeLocation, float(std::max(target.width, 1)),
                       float(std::max(target.height, 1)));
}

TextureHandle CloudShadowPass::declareMap(FrameGraph& graph, TextureHandle depth,
                                          const CloudDensityTexture& density,
                                          const CloudFrameSettings& clouds,
                                          const CloudShadowSettings& shadow) const {
    const CloudShadowPass* self = this;
    const CloudDensityTexture* densityTexture = &density;
    Pass& pass = map_.addPass(graph, "cloud shadow map",
                              [self, clouds, shadow, depth, densityTexture](PassContext& ctx) {
                                  self->setMapUniforms(clouds, shadow, ctx.targetSize());
                                  self->map_.draw({densityTexture->name(), ctx.native(depth)});
                              });
    TextureHandle map = pass.create("clouds.shadow", {TextureSize::output(), TextureFormat::R16F},
                                    TextureUsage::ColorAttachment);
    // The depth, then two density taps (two scales) per sample along the sun's ray.
    pass.read(depth).setTaps(1 + 2 * std::clamp(shadow.samples, 0, kCloudMaxSteps));
    return map;
}

TextureHandle CloudShadowPass::declare(FrameGraph& graph, const CloudShadowInputs& inputs,
                                       const CloudDensityTexture& density, const CloudFrameSettings& clouds,
                                       const CloudShadowSettings& shadow) const {
    TextureHandle map = declareMap(graph, inputs.depth, density, clouds, shadow);
    const FullscreenPass* apply = &apply_;
    const float sunShare = std::isfinite(shadow.sunShare) ? std::clamp(shadow.sunShare, 0.0f, 1.0f) : 0.0f;
    PassState multiply = FullscreenPass::state();
    multiply.blend = true;
    // dst x src for colour, alpha kept: result = scene x factor.
    BlendFunction times;
    times.srcRgb = BlendFactor::Zero;
    times.dstRgb = BlendFactor::SrcColor;
    times.srcAlpha = BlendFactor::Zero;
    times.dstAlpha = BlendFactor::One;
    multiply.blendFunction = times;
    apply_
        .addPass(graph, "cloud shadow apply",
                 [apply, map, sunShare](PassContext& ctx) {
                     glProgramUniform1f(apply->program(), glsl::kCloudShadowSunShareLocation, sunShare);
                     apply->draw({ctx.native(map)});
                 })
        .read(map)
        .modify(inputs.color, TextureUsage::ColorAttachment)
        .setState(multiply)
        .setTaps(1);
    return map;
}

}  // namespace fx
