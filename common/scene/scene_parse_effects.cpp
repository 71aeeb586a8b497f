// Reads "emitters", "clouds" and "postEffects".
#include "base/log.hpp"
#include "base/message_text.hpp"
#include "scene/scene_parse.hpp"

namespace fx {
namespace {

// Particle buffers are sized from rate x lifetime; this keeps a typo from asking for gigabytes.
constexpr double kMaxLiveParticles = 100000.0;

glm::vec4 readParticleColor(JsonFieldReader& reader, std::string_view key, glm::vec4 fallback) {
    glm::vec4 color = reader.vec4(key, fallback, kHdrColorRange);
    if (color.a > 1.0f)
        failField(indexPath(reader.pathOf(key), 3),
                  cat("alpha ", formatNumber(color.a), " is out of range [0, 1]"));
    return color;
}

CloudNoise parseCloudNoise(JsonFieldReader& reader, CloudNoise noise) {
    noise.scale = readSetting(reader, "scale", "clouds[0].noise[0].scale", noise.scale);  // every layer's
    noise.scroll = reader.vec2("scroll", noise.scroll, NumberRange::closed(-10.0, 10.0));
    reader.reportUnknown();
    return noise;
}

// The settings below start lessons' parameters: their ranges are declared in scene/scene_settings.cpp.
BloomSettings parseBloom(JsonFieldReader& reader) {
    BloomSettings bloom;
    bloom.threshold = readSetting(reader, "threshold", "postEffects.bloom.threshold", bloom.threshold);
    bloom.knee = readSetting(reader, "knee", "postEffects.bloom.knee", bloom.knee);
    bloom.intensity = readSetting(reader, "intensity", "postEffects.bloom.intensity", bloom.intensity);
    bloom.levels = readIntegerSetting(reader, "levels", "postEffects.bloom.levels", bloom.levels);
    reader.reportUnknown();
    return bloom;
}

ColorMatrixSettings parseColorMatrix(JsonFieldReader& reader) {
    ColorMatrixSettings settings;
    settings.preset = reader.requiredEnumeration<ColorMatrixPreset>("preset");
    settings.amount = readSetting(reader, "amount", "postEffects.colorMatrix.amount", settings.amount);
    reader.reportUnknown();
    return settings;
}

RadialBlurSettings parseRadialBlur(JsonFieldReader& reader) {
    RadialBlurSettings blur;
    blur.center = reader.vec2("center", blur.center, settingRange("postEffects.radialBlur.center[0]"));
    blur.length = readSetting(reader, "length", "postEffects.radialBlur.length", blur.length);
    blur.start = readSetting(reader, "start", "postEffects.radialBlur.start", blur.start);
    blur.taps = readIntegerSetting(reader, "taps", "postEffects.radialBlur.taps", blur.taps);
    reader.reportUnknown();
    return blur;
}

DepthOfFieldSettings parseDepthOfField(JsonFieldReader& reader) {
    DepthOfFieldSettings dof;
    dof.maxCocPixels = readSetting(reader, "maxCoc", "postEffects.depthOfField.maxCoc", dof.maxCocPixels);
    dof.taps = readIntegerSetting(reader, "taps", "postEffects.depthOfField.taps", dof.taps);
    reader.reportUnknown();
    return dof;
}

ToneMapSettings parseToneMap(JsonFieldReader& reader) {
    ToneMapSettings toneMap;
    // The operator names before the tone curve had one vocabulary; say what they are called now.
    if (reader.has("operator") && reader.required("operator").is_string()) {
        const std::string old = reader.required("operator").get<std::string>();
        if (old == "linear" || old == "aces")
            reader.fail("operator", cat("\"", old, "\" is now called \"", old == "aces" ? "filmic" : "clip",
                                        "\" (allowed: ", allowedNames<ToneCurve>(), ")"));
    }
    toneMap.curve = reader.enumeration<ToneCurve>("operator", toneMap.curve);
    toneMap.exposure = readSetting(reader, "exposure", "postEffects.toneMap.exposure", toneMap.exposure);
    reader.reportUnknown();
    return toneMap;
}

// Reads postEffects.<name> with `parse` when the scene asks for that effect.
template <class Settings, class Parse>
void parseEffect(JsonFieldReader& post, PostEffect effect, std::optional<Settings>& out, Parse parse) {
    std::string_view name = enumName(effect);
    if (!post.has(name)) return;
    auto reader = post.object(name);
    out = parse(reader);
}

}  // namespace

ParticleEmitter parseEmitter(JsonFieldReader& reader, const AssetPathReader& assets) {
    ParticleEmitter emitter;
    emitter.name = reader.text("name", "");
    emitter.kind = reader.enumeration<EmitterKind>("kind", emitter.kind);
    emitter.position = reader.requiredVec3("position", kCoordinateRange);
    emitter.ratePerSecond = reader.number("rate", emitter.ratePerSecond, NumberRange::aboveZero(1.0e4));
    emitter.lifetimeSeconds =
        reader.number("lifetime", emitter.lifetimeSeconds, NumberRange::aboveZero(60.0));
    double alive = double(emitter.ratePerSecond) * double(emitter.lifetimeSeconds);
    if (alive > kMaxLiveParticles)
        reader.fail("rate", cat("rate x lifetime = ", formatNumber(alive),
                                " particles alive at once; at most ", kMaxLiveParticles));
    emitter.startSize = reader.number("startSize", emitter.startSize, NumberRange::aboveZero(100.0));
    emitter.endSize = reader.number("endSize", emitter.endSize, NumberRange::closed(0.0, 100.0));
    emitter.startColor = readParticleColor(reader, "startColor", emitter.startColor);
    emitter.endColor = readParticleColor(reader, "endColor", emitter.endColor);
    emitter.riseSpeed = reader.number("riseSpeed", emitter.riseSpeed, NumberRange::closed(-100.0, 100.0));
    emitter.spinDegreesPerSecond =
        reader.number("spin", emitter.spinDegreesPerSecond, NumberRange::closed(-3600.0, 3600.0));
    emitter.spread = reader.number("spread", emitter.spread, NumberRange::closed(0.0, 100.0));
    emitter.sprite = assets.optional(reader, "sprite");
    emitter.seed = reader.integer("seed", emitter.seed, NumberRange::closed(0, 2147483647.0));
    reader.reportUnknown();
    return emitter;
}

CloudLayer parseCloudLayer(JsonFieldReader& reader, const AssetPathReader& assets) {
    CloudLayer cloud;
    cloud.name = reader.text("name", "");
    cloud.bottom = readSetting(reader, "bottom", "clouds[0].bottom", cloud.bottom);  // every layer's
    cloud.top = readSetting(reader, "top", "clouds[0].top", cloud.top);
    if (cloud.bottom >= cloud.top)
        reader.fail("bottom", cat(formatNumber(cloud.bottom), " is not below top (", formatNumber(cloud.top),
                                  "); the slab would have no thickness"));
    cloud.densityTexture = assets.required(reader, "densityTexture");
    if (reader.has("noise")) {
        const nlohmann::json& noise = reader.required("noise");
        std::string path = reader.pathOf("noise");
        if (!noise.is_array())
            failField(path, cat("expected an array of 2 objects, got ", describeJsonType(noise)));
        if (noise.size() != cloud.noise.size())
            failField(path, cat("expected ", cloud.noise.size(), " noise layers, got ", noise.size()));
        for (std::size_t i = 0; i < cloud.noise.size(); ++i) {
            auto layer = reader.child(noise[i], indexPath(path, i));
            cloud.noise[i] = parseCloudNoise(layer, cloud.noise[i]);
        }
    }
    // 1 leaves no cloud: the march is not drawn then (effects/clouds/cloud_march.hpp: thresholdClears), so
    // the shader's division by (1 - threshold) never meets 0.
    cloud.threshold = readSetting(reader, "threshold", "clouds[0].threshold", cloud.threshold);
    cloud.steps = readIntegerSetting(reader, "steps", "clouds[0].steps", cloud.steps);
    cloud.color = reader.vec3("color", cloud.color, kHdrColorRange);
    reader.reportUnknown();
    return cloud;
}

PostEffects parsePostEffects(JsonFieldReader& reader, const Camera& camera) {
    PostEffects post;
    parseEffect(reader, PostEffect::bloom, post.bloom, parseBloom);
    parseEffect(reader, PostEffect::colorMatrix, post.colorMatrix, parseColorMatrix);
    parseEffect(reader, PostEffect::radialBlur, post.radialBlur, parseRadialBlur);
    parseEffect(reader, PostEffect::depthOfField, post.depthOfField, parseDepthOfField);
    parseEffect(reader, PostEffect::toneMap, post.toneMap, parseToneMap);
    if (post.depthOfField && !camera.lens)
        reader.fail(
            "depthOfField",
            "needs a physical lens: give camera.lens (focal length, f-number, focus distance) instead of camera.fovY");
    reader.reportUnknown("post effect");
    return post;
}

}  // namespace fx
