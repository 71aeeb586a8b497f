#include "scene/scene_writer.hpp"
#include "base/json_text.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include <nlohmann/json.hpp>

#include "base/log.hpp"
#include "scene/scene_enums.hpp"
#include "scene/scene_settings.hpp"

namespace fx {
namespace {

using Json = nlohmann::ordered_json;  // keeps the fields in the order a person would write them

// The shortest decimal that reads back as the same float, as a double: 0.1f is written "0.1", not
// "0.10000000149011612", and still loads as exactly 0.1f.
double shortestDecimal(float value) {
    char text[32];
    for (int digits = 1; digits <= 9; ++digits) {
        std::snprintf(text, sizeof text, "%.*g", digits, double(value));
        double decimal = std::strtod(text, nullptr);
        if (static_cast<float>(decimal) == value) return decimal;
    }
    return double(value);
}

// Whole numbers are written without ".0", as a person would write them; infinity (a focus distance) as
// the word the reader takes, since JSON has no number for it.
Json number(float value) {
    if (std::isinf(value)) return value > 0 ? "infinity" : "-infinity";
    double decimal = shortestDecimal(value);
    if (std::fabs(decimal) < 1.0e15 && std::floor(decimal) == decimal)
        return static_cast<std::int64_t>(decimal);
    return decimal;
}

template <int N>
Json vector(const glm::vec<N, float>& value) {
    Json array = Json::array();
    for (int i = 0; i < N; ++i) array.push_back(number(value[i]));
    return array;
}

template <class E>
Json name(E value) {
    return std::string(enumName(value));
}

Json lensJson(const Lens& lens) {
    return Json{{"focalLength", number(lens.focalLengthMm)},
                {"sensorWidth", number(lens.sensorWidthMm)},
                {"fNumber", number(lens.fNumber)},
                {"focusDistance", number(lens.focusDistanceM)}};
}

Json cameraJson(const Camera& camera) {
    Json json{{"position", vector(camera.position)}};
    if (camera.aim == CameraAim::target) {
        json["target"] = vector(camera.target);
    } else {
        json["yaw"] = number(camera.yawDegrees);
        json["pitch"] = number(camera.pitchDegrees);
    }
    if (camera.lens)
        json["lens"] = lensJson(*camera.lens);
    else
        json["fovY"] = number(camera.fovYDegrees);
    json["near"] = number(camera.near);
    json["far"] = number(camera.far);
    return json;
}

Json shadowJson(const ShadowSettings& shadow) {
    return Json{{"casts", shadow.casts},           {"mapSize", shadow.mapSize},
                {"bias", number(shadow.bias)},     {"normalOffset", number(shadow.normalOffset)},
                {"filterTaps", shadow.filterTaps}, {"extent", number(shadow.extent)}};
}

Json lightGridJson(const LightGrid& grid) {
    Json json = Json::object();
    if (!grid.name.empty()) json["name"] = grid.name;
    json["center"] = vector(grid.center);
    json["count"] = Json::array({grid.count.x, grid.count.y});
    json["spacing"] = Json::array({number(grid.spacing.x), number(grid.spacing.y)});
    json["radius"] = number(grid.radius);
    json["intensity"] = number(grid.intensity);
    json["saturation"] = number(grid.saturation);
    json["seed"] = grid.seed;
    return json;
}

Json lightJson(const Light& light) {
    Json json{{"type", name(light.type)}};
    if (!light.name.empty()) json["name"] = light.name;
    json["color"] = vector(light.color);
    json["intensity"] = number(light.intensity);
    if (light.type != LightType::directional) {
        json["position"] = vector(light.position);
        json["radius"] = number(light.radius);
    }
    if (light.type != LightType::point) json["direction"] = vector(light.direction);
    if (light.type == LightType::spot) {
        json["innerCone"] = number(light.innerConeDegrees);
        json["outerCone"] = number(light.outerConeDegrees);
    }
    if (light.type == LightType::directional) json["shadow"] = shadowJson(light.shadow);
    return json;
}

Json primitiveJson(const Primitive& primitive) {
    Json json{{"shape", name(primitive.shape)}};
    switch (primitive.shape) {
        case PrimitiveShape::plane:
            json["size"] = vector(primitive.planeSize);
            break;
        case PrimitiveShape::box:
            json["size"] = vector(primitive.boxSize);
            break;
        case PrimitiveShape::sphere:
            json["radius"] = number(primitive.radius);
            break;
        case PrimitiveShape::cylinder:
        case PrimitiveShape::capsule:
            json["radius"] = number(primitive.radius);
            json["height"] = number(primitive.height);
            break;
    }
    return json;
}

Json materialJson(const Material& material) {
    Json json{{"baseColor", vector(material.baseColor)}};
    if (!material.baseColorTexture.empty()) json["baseColorTexture"] = material.baseColorTexture.path;
    json["emissive"] = vector(material.emissive);
    json["emissiveStrength"] = number(material.emissiveStrength);
    return json;
}

Json motionJson(const Motion& motion) {
    Json json{{"type", name(motion.type)}};
    if (motion.type == MotionType::circle) json["radius"] = number(motion.radius);
    if (motion.type == MotionType::bob) json["amplitude"] = number(motion.amplitude);
    if (motion.type != MotionType::none) {
        json["period"] = number(motion.periodSeconds);
        json["phase"] = number(motion.phaseDegrees);
    }
    return json;
}

Json objectJson(const SceneObject& object) {
    Json json = Json::object();
    if (!object.name.empty()) json["name"] = object.name;
    if (object.primitive)
        json["primitive"] = primitiveJson(*object.primitive);
    else
        json["gltf"] = object.gltf.path;
    // Parts left at their defaults are left out, so a saved scene reads like a written one.
    if (object.transform != Transform{}) {
        json["transform"] = Json{{"position", vector(object.transform.position)},
                                 {"rotation", vector(object.transform.rotationDegrees)},
                                 {"scale", vector(object.transform.scale)}};
    }
    if (object.material != Material{}) json["material"] = materialJson(object.material);
    if (!object.castsShadows) json["castsShadows"] = false;
    if (!object.receivesShadows) json["receivesShadows"] = false;
    if (!object.animation.clips.empty()) {
        const auto& clips = object.animation.clips;
        json["animation"] = Json{{"clip", clips.size() == 1 ? Json(clips[0]) : Json(clips)},
                                 {"speed", number(object.animation.speed)}};
    }
    if (object.moves()) json["motion"] = motionJson(object.motion);
    if (object.mirror) json["mirror"] = Json{{"strength", number(object.mirror->strength)}};
    return json;
}

Json emitterJson(const ParticleEmitter& emitter) {
    Json json = Json::object();
    if (!emitter.name.empty()) json["name"] = emitter.name;
    json["kind"] = name(emitter.kind);
    json["position"] = vector(emitter.position);
    json["rate"] = number(emitter.ratePerSecond);
    json["lifetime"] = number(emitter.lifetimeSeconds);
    json["startSize"] = number(emitter.startSize);
    json["endSize"] = number(emitter.endSize);
    json["startColor"] = vector(emitter.startColor);
    json["endColor"] = vector(emitter.endColor);
    json["riseSpeed"] = number(emitter.riseSpeed);
    json["spin"] = number(emitter.spinDegreesPerSecond);
    json["spread"] = number(emitter.spread);
    if (!emitter.sprite.empty()) json["sprite"] = emitter.sprite.path;
    json["seed"] = emitter.seed;
    return json;
}

Json cloudJson(const CloudLayer& cloud) {
    Json json = Json::object();
    if (!cloud.name.empty()) json["name"] = cloud.name;
    json["bottom"] = number(cloud.bottom);
    json["top"] = number(cloud.top);
    json["densityTexture"] = cloud.densityTexture.path;
    Json noise = Json::array();
    for (const auto& layer : cloud.noise)
        noise.push_back(Json{{"scale", number(layer.scale)}, {"scroll", vector(layer.scroll)}});
    json["noise"] = noise;
    json["threshold"] = number(cloud.threshold);
    json["steps"] = cloud.steps;
    json["color"] = vector(cloud.color);
    return json;
}

// Every effect the scene asks for, with the settings scene/scene_settings.cpp declares for it, in its
// order: "center[0]" and "center[1]" make one array.
Json postEffectsJson(const Scene& scene) {
    const std::vector<SettingText> values = sceneSettings(scene);
    Json json = Json::object();
    for (PostEffect effect : {PostEffect::bloom, PostEffect::colorMatrix, PostEffect::radialBlur,
                              PostEffect::depthOfField, PostEffect::toneMap}) {
        if (!scene.postEffects.wants(effect)) continue;
        const std::string prefix = cat("postEffects.", enumName(effect), ".");
        Json fields = Json::object();
        for (const SettingSpec* spec : settingsUnder(prefix)) {
            auto value = std::find_if(values.begin(), values.end(),
                                      [&](const SettingText& v) { return v.setting == spec->path; });
            if (value == values.end()) continue;
            Json written = spec->type == ParamType::Choice
                               ? Json(value->text)
                               : number(std::strtof(value->text.c_str(), nullptr));
            std::string field = settingField(*spec, prefix);
            if (auto bracket = field.find('['); bracket != std::string::npos)
                fields[field.substr(0, bracket)].push_back(written);
            else
                fields[field] = written;
        }
        json[std::string(enumName(effect))] = fields;
    }
    return json;
}

// nlohmann puts every array element on its own line; a vector reads better as [0, 1.5, -2].
std::string withNumberArraysOnOneLine(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    bool inString = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        char c = text[i];
        if (inString) {
            out += c;
            if (c == '\\' && i + 1 < text.size())
                out += text[++i];
            else if (c == '"')
                inString = false;
            continue;
        }
        if (c == '"') inString = true;
        std::size_t close = c == '[' ? text.find_first_of("[]{\"", i + 1) : std::string::npos;
        if (close == std::string::npos || text[close] != ']') {
            out += c;
            continue;
        }
        // Only numbers, commas and white space up to the closing bracket: join them on one line.
        out += '[';
        bool pendingSpace = false;
        for (std::size_t j = i + 1; j < close; ++j) {
            char d = text[j];
            if (d == ' ' || d == '\n') continue;
            if (pendingSpace) out += ' ';
            out += d;
            pendingSpace = d == ',';
        }
        out += ']';
        i = close;
    }
    return out;
}

template <class T, class ToJson>
Json arrayOf(const std::vector<T>& items, ToJson toJson) {
    Json array = Json::array();
    for (const auto& item : items) array.push_back(toJson(item));
    return array;
}

}  // namespace

std::string saveScene(const Scene& scene) {
    Json json = Json::object();
    json["version"] = kSceneFormatVersion;
    json["name"] = scene.name;
    if (!scene.description.empty()) json["description"] = scene.description;
    json["background"] = vector(scene.background);
    json["ambient"] = vector(scene.ambient);
    json["camera"] = cameraJson(scene.camera);
    json["lights"] = arrayOf(scene.lights, lightJson);
    if (!scene.lightGrids.empty()) json["lightGrids"] = arrayOf(scene.lightGrids, lightGridJson);
    json["objects"] = arrayOf(scene.objects, objectJson);
    if (!scene.emitters.empty()) json["emitters"] = arrayOf(scene.emitters, emitterJson);
    if (!scene.clouds.empty()) json["clouds"] = arrayOf(scene.clouds, cloudJson);
    Json post = postEffectsJson(scene);
    if (!post.empty()) json["postEffects"] = post;
    return withNumberArraysOnOneLine(dumpJson(json, 2)) + "\n";
}

}  // namespace fx
