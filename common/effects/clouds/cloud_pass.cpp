#include "effects/clouds/cloud_pass.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>

#include "base/log.hpp"
#include "effects/clouds/clouds_bindings.hpp"
#include "gl/texture_image.hpp"

namespace fx {
namespace {

// The feature bits each stage's code reads (clouds.frag): the others are left out of the program's
// choices, so settings that draw the same picture share one program.
constexpr int kPlaneFeatures = cloudRejectBehind | cloudTwoScales | cloudDepthAware;
constexpr int kMarchFeatures = cloudTwoScales | cloudDepthAware | cloudEyeInside | cloudShadows |
                               cloudThreshold | cloudHeightShaping | cloudDistanceOcclusion |
                               cloudBeerLambert;

// Four PCF taps a sample: 8 samples already cost 8 lookups a pixel, and the clouds are soft.
constexpr int kCloudShadowTaps = 4;

bool finite(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

}  // namespace

const char* cloudDitherName(CloudDither dither) {
    switch (dither) {
        case CloudDither::none:
            return "none";
        case CloudDither::bayer:
            return "Bayer 4x4";
        case CloudDither::ign:
            return "interleaved gradient noise";
        case CloudDither::r2:
            return "R2 (blue-noise-like)";
    }
    return "?";
}

glm::vec4 cloudShaderOffsets(const CloudFrameSettings& s) {
    // uv = (p - camera) * scale + (camera * scale + scroll): the second bracket in double, wrapped.
    glm::dvec3 camera(s.cameraPosition);
    glm::vec4 out;
    for (int layer = 0; layer < 2; ++layer) {
        double scale = layer == 0 ? s.scales.x : s.scales.y;
        if (!std::isfinite(scale) || !std::isfinite(camera.x) || !std::isfinite(camera.z)) scale = 0.0;
        out[layer * 2 + 0] = float(wrapUnit(camera.x * scale + double(s.scrollOffset[layer * 2 + 0])));
        out[layer * 2 + 1] = float(wrapUnit(camera.z * scale + double(s.scrollOffset[layer * 2 + 1])));
    }
    return out;
}

void setCloudCameraUniforms(GLuint prog, const CloudFrameSettings& s) {
    glm::mat4 inverseProjection = glm::inverse(s.projection);
    if (!finite(inverseProjection)) inverseProjection = glm::mat4(1.0f);
    glm::mat3 rotation = glm::transpose(glm::mat3(s.view));  // the inverse of a rotation
    glProgramUniformMatrix4fv(prog, glsl::kCloudsInverseProjectionLocation, 1, GL_FALSE,
                              glm::value_ptr(inverseProjection));
    glProgramUniformMatrix3fv(prog, glsl::kCloudsViewToWorldRotationLocation, 1, GL_FALSE,
                              glm::value_ptr(rotation));
    glProgramUniform3fv(prog, glsl::kCloudsCameraPositionLocation, 1, glm::value_ptr(s.cameraPosition));
    glm::vec4 offsets = cloudShaderOffsets(s);
    glProgramUniform4fv(prog, glsl::kCloudsOffsetsLocation, 1, glm::value_ptr(offsets));
}

ShadowLookup cloudShadowLookup(const ShadowLookup& sceneLookup) {
    ShadowLookup l = sceneLookup;
    l.normalOffsetMetres = 0.0f;
    l.filterTaps = std::min(sceneLookup.filterTaps, kCloudShadowTaps);
    return l;
}

Result<CloudDensityTexture> CloudDensityTexture::load(const std::string& path, bool mipmaps) {
    auto image = gl::readTextureImage(path);
    if (!image) return Error{image.error()};
    return fromImage(*image, mipmaps);
}

CloudDensityTexture CloudDensityTexture::fromImage(const ByteImage& rgba, bool mipmaps) {
    CloudDensityTexture t;
    // sRGB storage: sampling decodes it, as the chapter's loader does (its part 4: about 30 % of the
    // sky covered at threshold 0.5 this way, 93 % if the stored values were read raw).
    const int levels = mipmaps ? fullMipChainLength(rgba.width, rgba.height) : 1;
    t.texture_ = gl::Texture::create2D(TextureFormat::SRGB8_ALPHA8, rgba.width, rgba.height, levels,
                                       mipmaps ? "clouds.density (mipmapped)" : "clouds.density");
    glTextureSubImage2D(t.texture_.name(), 0, 0, 0, rgba.width, rgba.height, GL_RGBA, GL_UNSIGNED_BYTE,
                        rgba.texels.data());
    if (mipmaps) glGenerateTextureMipmap(t.texture_.name());
    glTextureParameteri(t.texture_.name(), GL_TEXTURE_MIN_FILTER,
                        mipmaps ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
    glTextureParameteri(t.texture_.name(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(t.texture_.name(), GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTextureParameteri(t.texture_.name(), GL_TEXTURE_WRAP_T, GL_REPEAT);
    return t;
}

std::uint64_t CloudDensityTexture::bytes() const {
    return texture_ ? textureBytes(texture_.spec()) : 0;
}

const FullscreenPass& CloudPass::programFor(const CloudFrameSettings& s) const {
    const int stage = int(s.stage);
    int features = 0;
    if (s.stage == CloudStage::plane) features = s.features & kPlaneFeatures;
    if (s.stage == CloudStage::march) features = s.features & kMarchFeatures;
    // Only the march jitters its start.
    const int dither = s.stage == CloudStage::march ? int(s.dither) : 0;
    return programs_.get({{"CLOUD_STAGE", stage},
                          {"CLOUD_FEATURES", features},
                          {"CLOUD_DITHER", dither},
                          {"CLOUD_PREMULTIPLY", s.premultiplied ? 1 : 0},
                          {"CLOUD_MIPMAPS", s.mipmaps && s.stage != CloudStage::screenTexture ? 1 : 0}});
}

PassState CloudPass::state() {
    PassState s = FullscreenPass::state();
    s.blend = true;
    s.blendFunction = BlendFunction::alpha();
    return s;
}

namespace {

// What a cloud march pass needs from its inputs, resolved once for both ways of declaring it.
struct MarchInputs {
    bool depth = false;
    bool shadows = false;
    TextureHandle depthTexture;
    TextureHandle shadowMap;
    ShadowLookup lookup;
};

MarchInputs marchInputs(const CloudInputs& inputs, CloudFrameSettings& s) {
    MarchInputs m;
    m.depth = (s.features & cloudDepthAware) != 0 && s.stage != CloudStage::screenTexture;
    m.shadows = (s.features & cloudShadows) != 0 && s.stage == CloudStage::march && inputs.shadow &&
                inputs.shadow->pass;
    m.depthTexture = inputs.depth;
    if (m.shadows) {
        m.shadowMap = inputs.shadow->map;
        m.lookup = cloudShadowLookup(inputs.shadow->lookup);
    }
    // The threshold that leaves no cloud: nothing to find, and no 1/(1 - threshold) in the shader.
    if ((s.features & cloudThreshold) && s.march.thresholdClears) s.march.drawn = false;
    return m;
}

// Every uniform of the march program `prog` for these settings.
void setMarchUniforms(GLuint prog, const CloudFrameSettings& s, Size2D target, const ShadowLookup* shadow) {
    setCloudCameraUniforms(prog, s);
    glm::vec4 rcs = s.march.rangeCountStep();
    if (!s.march.drawn) rcs = glm::vec4(s.march.bottom, s.march.bottom, 0.0f, 0.0f);
    glProgramUniform4fv(prog, glsl::kCloudsRangeCountStepLocation, 1, glm::value_ptr(rcs));
    glm::vec2 th = s.march.thresholdPair();
    glProgramUniform2fv(prog, glsl::kCloudsThresholdPairLocation, 1, glm::value_ptr(th));
    glm::vec3 colour = glm::clamp(s.color, glm::vec3(0.0f), glm::vec3(4096.0f));
    glProgramUniform3fv(prog, glsl::kCloudsColourLocation, 1, glm::value_ptr(colour));
    glProgramUniform2fv(prog, glsl::kCloudsScalesLocation, 1, glm::value_ptr(s.scales));
    glProgramUniform1f(prog, glsl::kCloudsShadowOffsetLocation, shadow ? cloudShadowOffset(*shadow) : 0.0f);
    glProgramUniform1i(prog, glsl::kCloudsFrameIndexLocation, std::max(s.frameIndex, 0));
    glProgramUniform1f(prog, glsl::kCloudsPlaneHeightLocation, s.planeHeight);
    glProgramUniform1i(prog, glsl::kCloudsDepthStrideLocation, std::max(s.depthStride, 1));
    glProgramUniform2f(prog, glsl::kCloudsTargetSizeLocation, float(std::max(target.width, 1)),
                       float(std::max(target.height, 1)));
}

// Texture lookups per pixel of clouds.frag, at most (a ray that leaves the slab or turns opaque stops
// early): the texture on the screen takes one; the plane the depth and its density taps; the march the
// depth, then per sample its density taps and, with object shadows, the shadow map's PCF taps.
double marchTaps(const CloudFrameSettings& s, const MarchInputs& m) {
    if (s.stage == CloudStage::screenTexture) return 1;
    const int density = (s.features & cloudTwoScales) ? 2 : 1;
    const int depth = m.depth ? 1 : 0;
    if (s.stage == CloudStage::plane) return depth + density;
    if (!s.march.drawn) return depth;
    const int shadow = m.shadows ? shadowLookupTaps(m.lookup) : 0;
    return depth + double(std::max(s.march.steps, 0)) * (density + shadow);
}

// The body both declares give their pass: the program resolved once, when the frame is declared.
Pass::Body marchBody(const FullscreenPass* program, const CloudFrameSettings& s, const MarchInputs& m,
                     const CloudDensityTexture* density) {
    return [program, s, m, density](PassContext& ctx) {
        const GLuint prog = program->program();
        setMarchUniforms(prog, s, ctx.targetSize(), m.shadows ? &m.lookup : nullptr);
        ShadowMap::bindForLookup(prog, m.shadows ? ctx.native(m.shadowMap) : 0,
                                 m.shadows ? m.lookup : ShadowLookup{});
        // Units 0 and 1, clouds.frag's bindings: the density, then the scene's depth.
        program->draw({density->name(), m.depth ? ctx.native(m.depthTexture) : 0});
    };
}

}  // namespace

Pass& CloudPass::declare(FrameGraph& graph, const CloudInputs& inputs, const CloudDensityTexture& density,
                         const CloudFrameSettings& settings) const {
    CloudFrameSettings s = settings;
    s.premultiplied = false;
    s.depthStride = 1;
    MarchInputs m = marchInputs(inputs, s);
    const FullscreenPass& program = programFor(s);
    Pass& pass = program.addPass(graph, "clouds", marchBody(&program, s, m, &density));
    pass.modify(inputs.color, TextureUsage::ColorAttachment).setState(state()).setTaps(marchTaps(s, m));
    if (m.depth) pass.read(inputs.depth);
    if (m.shadows) pass.read(m.shadowMap);
    return pass;
}

TextureHandle CloudPass::declareLayer(FrameGraph& graph, const CloudInputs& inputs,
                                      const CloudDensityTexture& density, CloudFrameSettings s, int divisor,
                                      const std::string& textureName) const {
    divisor = std::max(divisor, 1);
    s.premultiplied = true;
    s.depthStride = s.depthAtLayerPixels ? 1 : divisor;
    MarchInputs m = marchInputs(inputs, s);
    const FullscreenPass& program = programFor(s);
    Pass& pass = program.addPass(graph, "clouds march", marchBody(&program, s, m, &density));
    TextureHandle layer =
        pass.create(textureName, {TextureSize::outputFraction(1, divisor), TextureFormat::RGBA16F},
                    TextureUsage::ColorAttachment);
    pass.setTaps(marchTaps(s, m));
    if (m.depth) pass.read(inputs.depth);
    if (m.shadows) pass.read(m.shadowMap);
    return layer;
}

}  // namespace fx
