#pragma once
// The names scene files use for enumerations. The loader and the writer share these tables, so a name
// can only be spelled one way.
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "scene/scene.hpp"

namespace fx {

template <class E>
struct EnumName {
    E value;
    std::string_view name;
};

// One overload per enumeration; the argument only selects the table.
std::span<const EnumName<LightType>> enumNames(LightType);
std::span<const EnumName<PrimitiveShape>> enumNames(PrimitiveShape);
std::span<const EnumName<MotionType>> enumNames(MotionType);
std::span<const EnumName<EmitterKind>> enumNames(EmitterKind);
std::span<const EnumName<ColorMatrixPreset>> enumNames(ColorMatrixPreset);
std::span<const EnumName<ToneCurve>> enumNames(ToneCurve);
std::span<const EnumName<PostEffect>> enumNames(PostEffect);

template <class E>
std::string_view enumName(E value) {
    for (const auto& entry : enumNames(E{}))
        if (entry.value == value) return entry.name;
    return "?";
}

template <class E>
std::optional<E> enumFromName(std::string_view name) {
    for (const auto& entry : enumNames(E{}))
        if (entry.name == name) return entry.value;
    return std::nullopt;
}

// The names in order, as a Choice parameter lists them (its index is the enumerator's value).
template <class E>
std::vector<std::string> enumNameList() {
    std::vector<std::string> list;
    for (const auto& entry : enumNames(E{})) list.emplace_back(entry.name);
    return list;
}

// "plane, box, sphere": the allowed names, for error messages.
template <class E>
std::string allowedNames() {
    std::string list;
    for (const auto& entry : enumNames(E{})) {
        if (!list.empty()) list += ", ";
        list += entry.name;
    }
    return list;
}

}  // namespace fx
