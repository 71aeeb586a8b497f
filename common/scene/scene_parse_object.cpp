// Reads one entry of "objects": what it is (primitive or glTF), where, its material and how it moves.
#include "base/log.hpp"
#include "base/message_text.hpp"
#include "scene/scene_limits.hpp"
#include "scene/scene_parse.hpp"

namespace fx {
namespace {

Primitive parsePrimitive(JsonFieldReader& reader) {
    Primitive primitive;
    primitive.shape = reader.requiredEnumeration<PrimitiveShape>("shape");
    const std::string notForShape = cat("not used by a ", enumName(primitive.shape));
    switch (primitive.shape) {
        case PrimitiveShape::plane:
            primitive.planeSize = reader.vec2("size", primitive.planeSize, kLengthRange);
            reader.unused("radius", notForShape);
            reader.unused("height", notForShape);
            break;
        case PrimitiveShape::box:
            primitive.boxSize = reader.vec3("size", primitive.boxSize, kLengthRange);
            reader.unused("radius", notForShape);
            reader.unused("height", notForShape);
            break;
        case PrimitiveShape::sphere:
            primitive.radius = reader.number("radius", primitive.radius, kLengthRange);
            reader.unused("size", notForShape);
            reader.unused("height", notForShape);
            break;
        case PrimitiveShape::cylinder:
        case PrimitiveShape::capsule:
            primitive.radius = reader.number("radius", primitive.radius, kLengthRange);
            primitive.height = reader.number("height", primitive.height, kLengthRange);
            reader.unused("size", notForShape);
            break;
    }
    // The capsule's height includes both half-sphere caps, so it can be no shorter than their diameter.
    if (primitive.shape == PrimitiveShape::capsule && primitive.height < 2.0f * primitive.radius)
        reader.fail("height", cat(formatNumber(primitive.height),
                                  " is less than the diameter of the caps (2 x radius = ",
                                  formatNumber(2.0f * primitive.radius), ")"));
    reader.reportUnknown();
    return primitive;
}

Transform parseTransform(JsonFieldReader& reader) {
    Transform transform;
    transform.position = reader.vec3("position", transform.position, kCoordinateRange);
    transform.rotationDegrees =
        reader.vec3("rotation", transform.rotationDegrees, NumberRange::closed(-3600, 3600));
    // Zero scale makes the normal matrix singular; negative scale turns the triangles inside out.
    transform.scale = reader.vec3("scale", transform.scale, kLengthRange);
    reader.reportUnknown();
    return transform;
}

Material parseMaterial(JsonFieldReader& reader, const AssetPathReader& assets) {
    Material material;
    material.baseColor = reader.vec3("baseColor", material.baseColor, kUnitRange);
    material.baseColorTexture = assets.optional(reader, "baseColorTexture");
    material.emissive = reader.vec3("emissive", material.emissive, kHdrColorRange);
    material.emissiveStrength = reader.number("emissiveStrength", material.emissiveStrength, kHdrColorRange);
    reader.reportUnknown();
    return material;
}

// "clip": "walk", ["upper", "lower"] or "*" (every clip in the file).
Animation parseAnimation(JsonFieldReader& reader) {
    Animation animation;
    const nlohmann::json& clip = reader.required("clip");
    const std::string path = reader.pathOf("clip");
    if (clip.is_string()) {
        animation.clips.push_back(clip.get<std::string>());
    } else if (clip.is_array()) {
        if (clip.empty()) reader.fail("clip", "the list of clips is empty");
        if (clip.size() > scene_limits::kMaxClipsPerObject)
            reader.fail("clip", cat(clip.size(), " clips; an object may play at most ",
                                    scene_limits::kMaxClipsPerObject));
        for (std::size_t i = 0; i < clip.size(); ++i) {
            if (!clip[i].is_string())
                failField(indexPath(path, i), cat("expected a clip name, got ", describeJsonType(clip[i])));
            const std::string& name = clip[i].get_ref<const std::string&>();
            if (name == "*")
                failField(indexPath(path, i), "\"*\" (every clip) stands alone: write \"clip\": \"*\"");
            for (const std::string& before : animation.clips)
                if (before == name)
                    failField(indexPath(path, i), cat("\"", excerpt(name), "\" is listed twice"));
            animation.clips.push_back(name);
        }
    } else {
        reader.fail("clip",
                    cat("expected a clip name, a list of names or \"*\", got ", describeJsonType(clip)));
    }
    for (std::size_t i = 0; i < animation.clips.size(); ++i)
        if (animation.clips[i].empty())
            failField(clip.is_array() ? indexPath(path, i) : path, "the clip name is empty");
    animation.speed = reader.number("speed", animation.speed, NumberRange::closed(-100.0, 100.0));
    reader.reportUnknown();
    return animation;
}

Motion parseMotion(JsonFieldReader& reader) {
    Motion motion;
    motion.type = reader.requiredEnumeration<MotionType>("type");
    const std::string notForType = cat("not used by a \"", enumName(motion.type), "\" motion");
    if (motion.type == MotionType::circle)
        motion.radius = reader.number("radius", motion.radius, kLengthRange);
    else
        reader.unused("radius", notForType);
    if (motion.type == MotionType::bob)
        motion.amplitude = reader.number("amplitude", motion.amplitude, kLengthRange);
    else
        reader.unused("amplitude", notForType);
    if (motion.type != MotionType::none) {
        motion.periodSeconds = reader.number("period", motion.periodSeconds, NumberRange::aboveZero(3600.0));
        motion.phaseDegrees = reader.number("phase", motion.phaseDegrees, NumberRange::closed(-360.0, 360.0));
    } else {
        reader.unused("period", notForType);
        reader.unused("phase", notForType);
    }
    reader.reportUnknown();
    return motion;
}

}  // namespace

SceneObject parseObject(JsonFieldReader& reader, const AssetPathReader& assets) {
    SceneObject object;
    object.name = reader.text("name", "");
    bool hasPrimitive = reader.has("primitive");
    bool hasGltf = reader.has("gltf");
    if (hasPrimitive && hasGltf) reader.fail("gltf", "an object is a primitive or a glTF model, not both");
    if (!hasPrimitive && !hasGltf)
        failField(reader.path(), "missing required field: give \"primitive\" or \"gltf\"");
    if (hasPrimitive) {
        auto primitiveReader = reader.object("primitive");
        object.primitive = parsePrimitive(primitiveReader);
    } else {
        object.gltf = assets.required(reader, "gltf");
    }
    if (reader.has("transform")) {
        auto transformReader = reader.object("transform");
        object.transform = parseTransform(transformReader);
    }
    if (reader.has("material")) {
        auto materialReader = reader.object("material");
        object.material = parseMaterial(materialReader, assets);
    }
    object.castsShadows = reader.boolean("castsShadows", object.castsShadows);
    object.receivesShadows = reader.boolean("receivesShadows", object.receivesShadows);
    if (reader.has("animation")) {
        if (hasPrimitive)
            reader.fail(
                "animation",
                "a primitive has no animation clips (only glTF models do); use \"motion\" to move it");
        auto animationReader = reader.object("animation");
        object.animation = parseAnimation(animationReader);
    }
    object.skinned = hasGltf && !object.animation.clips.empty();
    if (reader.has("motion")) {
        auto motionReader = reader.object("motion");
        object.motion = parseMotion(motionReader);
    }
    if (reader.has("mirror")) {
        if (!object.primitive || object.primitive->shape != PrimitiveShape::plane)
            reader.fail("mirror", "only a plane primitive can be a mirror (the reflection is planar)");
        auto mirrorReader = reader.object("mirror");
        Mirror mirror;
        mirror.strength = mirrorReader.number("strength", mirror.strength, kUnitRange);
        mirrorReader.reportUnknown();
        object.mirror = mirror;
    }
    reader.reportUnknown();
    return object;
}

}  // namespace fx
