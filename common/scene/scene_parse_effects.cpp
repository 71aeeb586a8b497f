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
    noise.scale = reader.number("scale", noise.scale, NumberRange::aboveZero(100.0));
    noise.scroll = reader.vec2("scroll", noise.scroll, NumberRange::closed(-10.0, 10.0));
    reader.reportUnknown();
    return noise;
}

BloomSettings parseBloom(JsonFieldReader& reader) {
    BloomSettings bloom;
    bloom.threshold = reader.number("threshold", bloom.threshold, NumberRange::closed(0.0, 1.0e4));
    bloom.knee = reader.number("knee", bloom.knee, kUnitRange);
    bloom.intensity = reader.number("intensity", bloom.intensity, NumberRange::closed(0.0, 100.0));
    bloom.levels = reader.integer("levels", bloom.levels, NumberRange::closed(1, 16));
    reader.reportUnknown();
    return bloom;
}

ColorMatrixSettings parseColorMatrix(JsonFieldReader& reader) {
    ColorMatrixSettings settings;
    settings.preset = reader.requiredEnumeration<ColorMatrixPreset>("preset");
    settings.amount = reader.number("amount", settings.amount, kUnitRange);
    reader.reportUnknown();
    return settings;
}

RadialBlurSettings parseRadialBlur(JsonFieldReader& reader) {
    RadialBlurSettings blur;
    blur.center = reader.vec2("center", blur.center, kUnitRange);
    blur.length = reader.number("length", blur.length, kUnitRange);
    blur.start = reader.number("start", blur.start, NumberRange::closed(0.0, 2.0));
    blur.taps = reader.integer("taps", blur.taps, NumberRange::closed(1, 64));
    reader.reportUnknown();
    return blur;
}

DepthOfFieldSettings parseDepthOfField(JsonFieldReader& reader) {
    DepthOfFieldSettings dof;
    dof.maxCocPixels = reader.number("maxCoc", dof.maxCocPixels, NumberRange::aboveZero(256.0));
    dof.taps = reader.integer("taps", dof.taps, NumberRange::closed(1, 128));
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
    toneMap.exposure = reader.number("exposure", toneMap.exposure, NumberRange::aboveZero(1000.0));
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
    const NumberRange heights = NumberRange::closed(-1.0e4, 1.0e5);
    cloud.bottom = reader.requiredNumber("bottom", heights);
    cloud.top = reader.requiredNumber("top", heights);
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
    // The shader divides by (1 - threshold) to stretch what is left of the density back to [0, 1].
    cloud.threshold = reader.number("threshold", cloud.threshold, NumberRange{0.0, 1.0, false, true});
    cloud.steps = reader.integer("steps", cloud.steps, NumberRange::closed(1, 512));
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
        reader.fail("depthOfField",
                    "needs a physical lens: give camera.lens (focal length, f-number, focus "
                    "distance) instead of camera.fovY");
    reader.reportUnknown("post effect");
    return post;
}

}  // namespace fx
