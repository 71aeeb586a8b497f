// Reads one entry of "lights". Which fields apply depends on the type; the others are warned about.
#include <algorithm>
#include <bit>
#include <cmath>

#include <glm/geometric.hpp>

#include "base/log.hpp"
#include "base/message_text.hpp"
#include "scene/scene_parse.hpp"

namespace fx {
namespace {

glm::vec3 readDirection(JsonFieldReader& reader) {
    glm::vec3 direction = reader.requiredVec3("direction", NumberRange::closed(-1.0e3, 1.0e3));
    if (!(glm::length(direction) > 1.0e-6f))
        reader.fail("direction", "has zero length, so it points nowhere");
    return direction;
}

ShadowSettings parseShadow(JsonFieldReader& reader) {
    ShadowSettings shadow;
    // Writing a shadow block means the light should cast, unless it says otherwise.
    shadow.casts = reader.boolean("casts", true);
    shadow.mapSize = reader.integer("mapSize", shadow.mapSize, NumberRange::closed(128, 8192));
    if (!std::has_single_bit(static_cast<unsigned>(shadow.mapSize)))
        reader.fail("mapSize", cat(shadow.mapSize, " is not a power of two (128, 256, ... 8192)"));
    shadow.bias = reader.number("bias", shadow.bias, NumberRange::closed(0.0, 0.1));
    shadow.normalOffset = reader.number("normalOffset", shadow.normalOffset, NumberRange::closed(0.0, 10.0));
    shadow.filterTaps = reader.integer("filterTaps", shadow.filterTaps, NumberRange::closed(1, 64));
    shadow.extent = reader.number("extent", shadow.extent, kLengthRange);
    reader.reportUnknown();
    return shadow;
}

}  // namespace

Light parseLight(JsonFieldReader& reader) {
    Light light;
    light.type = reader.requiredEnumeration<LightType>("type");
    light.name = reader.text("name", "");
    light.color = reader.vec3("color", light.color, kHdrColorRange);
    light.intensity = reader.number("intensity", light.intensity, NumberRange::closed(0.0, 1.0e5));
    const std::string typeName(enumName(light.type));
    const std::string notForType = cat("not used by a ", typeName, " light");

    if (light.type == LightType::directional) {
        light.direction = readDirection(reader);
        if (reader.has("shadow")) {
            auto shadowReader = reader.object("shadow");
            light.shadow = parseShadow(shadowReader);
        }
        reader.unused("position", cat(notForType, " (it is infinitely far away)"));
        reader.unused("radius", notForType);
    } else {
        light.position = reader.requiredVec3("position", kCoordinateRange);
        light.radius = reader.number("radius", light.radius, kLengthRange);
        reader.unused("shadow", "only directional lights cast shadows in fxlab");
    }

    if (light.type == LightType::spot) {
        light.direction = readDirection(reader);
        light.outerConeDegrees =
            reader.number("outerCone", light.outerConeDegrees, NumberRange{0.0, 89.0, true, false});
        light.innerConeDegrees =
            reader.number("innerCone", std::min(light.innerConeDegrees, light.outerConeDegrees),
                          NumberRange::closed(0.0, 89.0));
        if (light.innerConeDegrees > light.outerConeDegrees)
            reader.fail("innerCone", cat(formatNumber(light.innerConeDegrees), " is wider than outerCone (",
                                         formatNumber(light.outerConeDegrees),
                                         "); the light would brighten toward the edge"));
    } else {
        reader.unused("innerCone", notForType);
        reader.unused("outerCone", notForType);
        if (light.type == LightType::point)
            reader.unused("direction", cat(notForType, " (it shines every way)"));
    }
    reader.reportUnknown();
    return light;
}

LightGrid parseLightGrid(JsonFieldReader& reader) {
    LightGrid grid;
    grid.name = reader.text("name", "");
    grid.center = reader.requiredVec3("center", kCoordinateRange);
    glm::vec2 count = reader.vec2("count", glm::vec2(grid.count), NumberRange::closed(1, kMaxGridLights));
    if (count.x != std::floor(count.x) || count.y != std::floor(count.y))
        reader.fail("count", cat("[", count.x, ", ", count.y, "] is not two whole numbers"));
    grid.count = glm::ivec2(count);
    if (grid.lightCount() > kMaxGridLights)
        reader.fail("count", cat(grid.count.x, " x ", grid.count.y, " = ", grid.lightCount(),
                                 " lights; a grid may have at most ", kMaxGridLights));
    grid.spacing = reader.vec2("spacing", grid.spacing, kLengthRange);
    grid.radius = reader.number("radius", grid.radius, kLengthRange);
    grid.intensity = reader.number("intensity", grid.intensity, NumberRange::closed(0.0, 1.0e5));
    grid.saturation = reader.number("saturation", grid.saturation, kUnitRange);
    grid.seed = reader.integer("seed", grid.seed, NumberRange::closed(0, 1.0e9));
    reader.reportUnknown();
    return grid;
}

}  // namespace fx
